# frozen_string_literal: true

require 'language_server-protocol'
require 'json'
require 'open3'
require 'timeout'
require 'rbconfig'
require 'stringio'
require 'syskit/lsp/uri'

module Syskit
  module SelfTest
    # An editor's side of `syskit lsp`: bin/syskit lsp in a process of its
    # own, spoken to with the language_server-protocol gem's framing.
    # Messages from the server are read on a thread; #request waits for
    # its answer, #notification for the next notification of a method.
    class LSPClient
      Protocol = LanguageServer::Protocol
      TIMEOUT = Float(ENV.fetch('SYSKIT_LSP_TEST_TIMEOUT', '30'))

      BIN = File.expand_path('../../bin/syskit', __dir__)

      attr_reader :stderr

      def initialize(env:, chdir:)
        @stdin, stdout, @stderr_io, @thread =
          Open3.popen3(env, RbConfig.ruby, BIN, 'lsp', chdir: chdir, unsetenv_others: true)
        @writer = Protocol::Transport::Io::Writer.new(@stdin)
        @messages = Queue.new
        @pending = []
        @next_id = 0
        @stderr = +''
        @reader = Thread.new do
          StrictReader.new(stdout).read { |m| @messages << m }
        rescue StandardError => e
          @messages << e
        end
        @stderr_reader = Thread.new { @stderr << @stderr_io.read.to_s }
      end

      # The server's process id.
      def pid
        @thread.pid
      end

      def request(method, params = {})
        id = (@next_id += 1)
        @writer.write(id: id, method: method, params: params)
        take { |m| m[:id] == id && !m.key?(:method) }
      end

      def notify(method, params = {})
        @writer.write(method: method, params: params)
      end

      # Writes +bytes+ as they are (what no client should send).
      def send_raw(bytes)
        @stdin.write(bytes)
        @stdin.flush
      end

      # The notifications the block sends, written to the server at once
      # (as an editor sends the changes of fast typing).
      def at_once
        writer = @writer
        buffer = StringIO.new
        @writer = Protocol::Transport::Io::Writer.new(buffer)
        yield
      ensure
        @writer = writer
        @stdin.write(buffer.string)
        @stdin.flush
      end

      # The next notification +method+ that the block (if given) accepts;
      # the messages passed over are kept for later.
      def notification(method)
        take { |m| m[:method] == method && (!block_given? || yield(m[:params])) }[:params]
      end

      # The diagnostics published next for +path+.
      def diagnostics_of(path)
        uri = Syskit::LSP::URI.of(path)
        notification('textDocument/publishDiagnostics') { |params| params[:uri] == uri }[:diagnostics]
      end

      def open(path, text = File.read(path))
        notify('textDocument/didOpen', textDocument: { uri: Syskit::LSP::URI.of(path), languageId: 'ruby',
                                                       version: 1, text: text })
      end

      def change(path, text, version: 2)
        notify('textDocument/didChange', textDocument: { uri: Syskit::LSP::URI.of(path), version: version },
                                         contentChanges: [{ text: text }])
      end

      def position(path, line, character)
        { textDocument: { uri: Syskit::LSP::URI.of(path) }, position: { line: line, character: character } }
      end

      # Shuts the server down as editors do; returns its exit status.
      def close
        request('shutdown')
        notify('exit')
        @stdin.close
        @thread.value.exitstatus
      ensure
        @stdin.close unless @stdin.closed?
        @stderr_reader.join(TIMEOUT)
      end

      # Kills a server still running (a test that failed half way).
      def kill
        Process.kill('KILL', @thread.pid) if @thread.alive?
      rescue Errno::ESRCH
        nil
      end

      # The library's reader, which finds the Content-Length header wherever
      # it is in what comes before a message: this one also checks that
      # nothing else does (a line the app printed on stdout).
      class StrictReader < Protocol::Transport::Io::Reader
        def initialize(io)
          super(HeaderCheck.new(io))
        end
      end

      # The server's stdout, whose headers are checked as they are read.
      class HeaderCheck
        def initialize(io)
          @io = io
        end

        def gets(separator)
          header = @io.gets(separator)
          return header if header.nil? || header.match?(/\AContent-Length: \d+\r\n\r\n\z/)

          raise "stray output on the server's stdout: #{header.inspect}"
        end

        def read(size)
          @io.read(size)
        end

        def binmode
          @io.binmode
        end
      end

      private

      def take(&)
        Timeout.timeout(TIMEOUT) do
          found = @pending.find(&)
          return @pending.delete(found) if found

          loop do
            message = @messages.pop
            raise message if message.is_a?(Exception)
            return message if yield message

            @pending << message
          end
        end
      rescue Timeout::Error
        raise "no answer from syskit lsp in #{TIMEOUT} s; its stderr:\n#{@stderr}"
      end
    end
  end
end
