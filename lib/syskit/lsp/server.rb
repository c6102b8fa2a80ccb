# frozen_string_literal: true

module Syskit
  module LSP
    # The Language Server Protocol loop: messages read and written with the
    # framing of the language_server-protocol gem, each request answered by
    # the capability it names (see REQUESTS), the documents' diagnostics
    # published as they open, change and are saved (see Workspace).
    #
    # Nothing a request meets stops the server: an error is logged (on
    # +log+, the editor's server log) and answered as one.
    class Server
      include Queries

      Protocol = LanguageServer::Protocol
      ErrorCodes = Protocol::Constant::ErrorCodes

      REQUESTS = {
        'initialize' => :initialize_server, 'shutdown' => :shutdown,
        'textDocument/hover' => :hover, 'textDocument/definition' => :definition,
        'textDocument/completion' => :completion, 'textDocument/documentSymbol' => :document_symbols
      }.freeze

      NOTIFICATIONS = {
        'initialized' => :ignore, 'exit' => :exit_server,
        'textDocument/didOpen' => :did_open, 'textDocument/didChange' => :did_change,
        'textDocument/didSave' => :did_save, 'textDocument/didClose' => :did_close
      }.freeze

      # Characters after which editors ask for completions unprompted:
      # OroGen.lib. and Module::, the quote opening a name, a call's (.
      TRIGGER_CHARACTERS = ['.', ':', "'", '"', '('].freeze

      attr_reader :workspace

      def initialize(input, output, log: $stderr)
        @reader = Protocol::Transport::Io::Reader.new(input)
        @writer = Protocol::Transport::Io::Writer.new(output)
        @log = log
        @workspace = Workspace.new(log: log)
        @uris = {}
        @input = input
        @pending = {}
      end

      # Answers messages until the client says exit (or closes its end);
      # returns the exit status: 0 after a shutdown request, 1 otherwise, as
      # the protocol says.
      def run
        loop do
          @reader.read do |message|
            dispatch(message)
            return @shut_down ? 0 : 1 if @exiting

            check_pending unless more_input?
          end
          return @shut_down ? 0 : 1
        rescue JSON::ParserError, NoMethodError, ::TypeError => e
          # What the client framed wrong (no Content-Length header, not JSON,
          # not an object): skipped, the next message read.
          @log.puts "syskit lsp: skipped input that is not a protocol message (#{e.class})"
        end
      end

      private

      def dispatch(message)
        name = message[:method]
        if message.key?(:id) && name
          answer(message[:id], name, message[:params] || {})
        elsif name
          handler = NOTIFICATIONS[name]
          guarded(name) { send(handler, message[:params] || {}) } if handler
        end
      end

      def answer(id, name, params)
        check_pending
        handler = REQUESTS[name]
        return respond_error(id, ErrorCodes::METHOD_NOT_FOUND, "syskit lsp does not answer #{name}") unless handler

        failure = nil
        result = guarded(name, ->(e) { failure = e }) { send(handler, params) }
        return respond_error(id, ErrorCodes::INTERNAL_ERROR, "#{name} failed: #{failure.message}") if failure

        @writer.write(id: id, result: result)
      end

      # Runs a handler; what it raises is logged, given to +failed+ and
      # kept from the loop.
      def guarded(name, failed = nil)
        yield
      rescue StandardError, ScriptError, SystemStackError, SystemExit => e
        @log.puts "syskit lsp: #{name}: #{e.class}: #{e.message}"
        @log.puts((e.backtrace || []).first(20).map { |l| "    #{l}" })
        failed&.call(e)
        nil
      end

      def respond_error(id, code, message)
        @writer.write(id: id, error: { code: code, message: message })
      end

      def notify(method, params)
        @writer.write(method: method, params: params)
      end

      def initialize_server(params)
        # Clients say whether they show a diagnostic's related information
        # (Neovim and VS Code do, Emacs' eglot does not): the others get
        # the hint in the message.
        @hint_apart = params.dig(:capabilities, :textDocument, :publishDiagnostics, :relatedInformation) == true
        { capabilities: capabilities, serverInfo: { name: 'syskit', version: Syskit::VERSION } }
      end

      def capabilities
        sync = Protocol::Constant::TextDocumentSyncKind::FULL
        { textDocumentSync: { openClose: true, change: sync, save: { includeText: true } },
          hoverProvider: true, definitionProvider: true, documentSymbolProvider: true,
          completionProvider: { triggerCharacters: TRIGGER_CHARACTERS } }
      end

      def shutdown(_params)
        @shut_down = true
        nil
      end

      def exit_server(_params)
        @exiting = true
      end

      def ignore(_params); end

      def did_open(params)
        document = params[:textDocument]
        changed(document[:uri], document[:text])
      end

      # The whole text (the server asks for full synchronization).
      def did_change(params)
        text = params[:contentChanges]&.last&.dig(:text) or return
        changed(params.dig(:textDocument, :uri), text)
      end

      def did_save(params)
        path = URI.path(params.dig(:textDocument, :uri)) or return
        text = params[:text] || workspace.text(path) || File.read(path, encoding: 'UTF-8')
        changed(params.dig(:textDocument, :uri), text)
      end

      def did_close(params)
        check_pending
        uri = params.dig(:textDocument, :uri)
        path = URI.path(uri) or return
        workspace.close(path) { |file, diagnostics| publish(file, diagnostics) }
      end

      # The text is checked once the client has nothing more to say (see
      # #check_pending).
      def changed(uri, text)
        path = URI.path(uri) or return
        @uris[path] = uri
        @pending.delete(path)
        @pending[path] = text
      end

      # Checks the texts changed since the last check, each file's last
      # text only: while users type, editors send a change per keystroke,
      # faster than a check; those already superseded by the next one
      # waiting to be read are not checked. Requests check first, so that
      # they answer on what the editor shows.
      def check_pending
        changes = @pending
        @pending = {}
        changes.each do |path, text|
          guarded('check') { workspace.update(path, text) { |file, diagnostics| publish(file, diagnostics) } }
        end
      end

      # Whether another message is waiting to be read.
      def more_input?
        @input.ready?
      rescue IOError
        false
      end

      def publish(path, diagnostics)
        diagnostics = diagnostics.map { |d| Diagnostics.with_hint_in_message(d) } unless @hint_apart
        notify('textDocument/publishDiagnostics', uri: uri_of(path), diagnostics: diagnostics)
      end

      # The URI of +path+ as the editor gave it (they compare them as
      # strings, percent-encoding and all), else as URI.of writes it.
      def uri_of(path)
        @uris.fetch(path) { URI.of(path) }
      end
    end
  end
end
