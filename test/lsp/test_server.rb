# frozen_string_literal: true

require_relative '../helper'
require 'syskit/lsp'
require_relative 'lsp_client'

module Syskit
  # `syskit lsp` through the protocol, as an editor speaks it: bin/syskit lsp
  # in a process of its own, on a copy of the example app.
  class TestLSPServer < Minitest::Test
    include SelfTest

    # What Neovim and VS Code say they show of diagnostics.
    SHOWS_RELATED_INFORMATION = { textDocument: { publishDiagnostics: { relatedInformation: true } } }.freeze

    def setup
      @dir = Dir.mktmpdir('syskit-lsp')
      FileUtils.cp_r(File.join(GEM_ROOT, 'examples', 'awesome_robot'), @dir)
      @root = File.join(@dir, 'awesome_robot')
      @client = SelfTest::LSPClient.new(env: SelfTest.child_env, chdir: @dir)
      @initialized = @client.request('initialize', processId: Process.pid, rootUri: LSP::URI.of(@root),
                                                   capabilities: SHOWS_RELATED_INFORMATION)
      @client.notify('initialized')
    end

    def teardown
      @client&.kill
      FileUtils.rm_rf(@dir)
    end

    def file(relative)
      File.join(@root, relative)
    end

    PROFILE = 'models/profiles/live/base.rb'

    def test_it_advertises_what_it_answers_and_exits_as_asked
      capabilities = @initialized[:result][:capabilities]
      assert_equal 1, capabilities[:textDocumentSync][:change] # the whole text
      assert capabilities[:textDocumentSync][:save][:includeText]
      %i[hoverProvider definitionProvider documentSymbolProvider].each { |c| assert capabilities[c], c }
      assert_includes capabilities[:completionProvider][:triggerCharacters], '.'
      assert_equal 'syskit', @initialized[:result][:serverInfo][:name]
      assert_equal 0, @client.close
    end

    # Started at a terminal rather than by an editor: it says what it is.
    def test_at_a_terminal_it_says_it_is_for_editors
      require 'pty'
      PTY.spawn(SelfTest.child_env, RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), 'lsp',
                unsetenv_others: true) do |reader, writer, pid|
        assert_match(/speaks the Language Server Protocol.*editor\.md/, reader.gets)
        writer.write("\x04") # Ctrl-D: the end of its input
        Process.wait(pid)
      end
    end

    def test_input_that_is_not_a_message_is_skipped_and_said_in_the_log
      @client.send_raw("hello\r\n\r\n")
      @client.send_raw("Content-Length: 2\r\n\r\n[]")
      assert_equal 'syskit', @client.request('initialize', capabilities: {})[:result][:serverInfo][:name]
      assert_equal 0, @client.close
      assert_equal 2, @client.stderr.scan('syskit lsp: skipped input that is not a protocol message').size
    end

    def test_a_mistake_in_a_buffer_is_shown_at_its_line_with_its_hint_then_cleared_once_fixed
      path = file(PROFILE)
      text = File.read(path)
      @client.open(path, text)
      assert_equal [], @client.diagnostics_of(path)

      @client.change(path, text.sub('Ublox::F9', 'Ublox::F8'))
      diagnostic, = @client.diagnostics_of(path)
      assert_diagnostic(diagnostic, line: text.lines.index { |l| l.include?('Ublox::F9') },
                                    message: /uninitialized constant .*Ublox::F8/)
      hint = diagnostic[:relatedInformation].first
      assert_equal "hint: did you mean 'AwesomeRobot::Devices::GPS::Ublox::F9'?", hint[:message]
      assert_equal LSP::URI.of(path), hint[:location][:uri]
      assert_equal File.read(path), text, 'the file on disk is not touched'

      @client.change(path, text, version: 3)
      assert_equal [], @client.diagnostics_of(path)
      assert_equal 0, @client.close
    end

    # A client that does not show related information (Emacs' eglot) gets
    # the hint under the message.
    def test_a_client_without_related_information_gets_the_hint_in_the_message
      @client.kill
      @client = SelfTest::LSPClient.new(env: SelfTest.child_env, chdir: @dir)
      @client.request('initialize', processId: Process.pid, rootUri: LSP::URI.of(@root), capabilities: {})
      @client.notify('initialized')
      path = file(PROFILE)
      @client.open(path, File.read(path).sub('Ublox::F9', 'Ublox::F8'))
      diagnostic, = @client.diagnostics_of(path)
      assert_match(/\Auninitialized constant .*Ublox::F8\nhint: did you mean 'AwesomeRobot::Devices::GPS::Ublox::F9'\?\z/,
                   diagnostic[:message])
      assert_equal 0, @client.close
    end

    def assert_diagnostic(diagnostic, line:, message:, severity: 1)
      assert_equal line, diagnostic[:range][:start][:line]
      assert_equal severity, diagnostic[:severity]
      assert_equal 'syskit', diagnostic[:source]
      assert_match message, diagnostic[:message]
    end

    # The place of +needle+ in +text+ (+offset+ characters in), as a request's params.
    def at(path, text, needle, offset: 0)
      line = text.lines.index { |l| l.include?(needle) }
      @client.position(path, line, text.lines[line].index(needle) + offset)
    end

    # The example's profile, opened and checked; its path and text.
    def open_profile
      path = file(PROFILE)
      text = File.read(path)
      @client.open(path, text)
      @client.diagnostics_of(path)
      [path, text]
    end

    def test_hover_answers_markdown
      path, text = open_profile
      hover = @client.request('textDocument/hover', at(path, text, 'F9, as:'))[:result][:contents]
      assert_equal 'markdown', hover[:kind]
      assert_match(/device model.*Ublox::F9/, hover[:value])
    end

    def test_definition_answers_the_declaration_s_file_and_line
      path, text = open_profile
      f9 = file('models/devices/gps/ublox/f9.rb')
      definition, = @client.request('textDocument/definition', at(path, text, 'F9, as:'))[:result]
      assert_equal LSP::URI.of(f9), definition[:uri]
      assert_equal File.readlines(f9).index { |l| l.include?("device_type 'F9'") }, definition[:range][:start][:line]
    end

    def test_completion_answers_items_with_markdown_documentation
      path, text = open_profile
      completion = @client.request('textDocument/completion',
                                   at(path, text, "using_task_library 'can_open'", offset: 20))[:result]
      refute completion[:isIncomplete]
      canbus = completion[:items].find { |item| item[:label] == 'canbus' }
      assert_equal [9, 'task library'], canbus.values_at(:kind, :detail)
      assert_equal 'markdown', canbus[:documentation][:kind]
    end

    def test_document_symbols_answer_the_outline
      path, = open_profile
      symbols = @client.request('textDocument/documentSymbol', textDocument: { uri: LSP::URI.of(path) })[:result]
      assert_equal(['AwesomeRobot::Profiles::Live::Base'], symbols.map { |symbol| symbol[:name] })
      assert_includes symbols.first[:children].map { |child| child[:name] }, 'gps'
      assert_equal 0, @client.close
    end

    # A configuration file changed: the models stay loaded, and the
    # answers are about the new file.
    def test_completion_knows_a_section_added_to_a_configuration_buffer
      path, text = open_profile
      at_section = at(path, text, ".with_conf('default', 'aft')", offset: 23)
      labels = -> { @client.request('textDocument/completion', at_section)[:result][:items].map { |i| i[:label] } }
      assert_equal %w[default forward aft], labels.call
      conf = file('config/orogen/camera_gige::Task.yml')
      @client.open(conf, "#{File.read(conf)}--- name:night\nexposure: 20000\n")
      @client.diagnostics_of(conf)
      assert_equal %w[default forward aft night], labels.call
    end

    # Changes faster than checks: only the last text waiting is checked.
    def test_changes_sent_at_once_are_checked_once_on_the_last_text
      path, text = open_profile
      @client.at_once do
        (2..5).each { |version| @client.change(path, text.sub('Ublox::F9', "Ublox::F#{version}"), version: version) }
        @client.change(path, text.sub('Ublox::F9', 'Ublox::F10'), version: 6)
      end
      diagnostic, *others = @client.diagnostics_of(path)
      assert_empty others
      assert_match(/Ublox::F10\b/, diagnostic[:message])
      @client.change(path, text, version: 7)
      assert_equal [], @client.diagnostics_of(path)
    end

    def test_queries_answer_on_the_buffer_after_a_change_and_nothing_on_a_file_not_open
      path, text = open_profile
      # Two lines more at the top: the positions are the buffer's.
      changed = "# one\n# two\n#{text}"
      @client.change(path, changed)
      @client.diagnostics_of(path)
      hover = @client.request('textDocument/hover', at(path, changed, 'F9, as:'))[:result]
      assert_match(/Ublox::F9/, hover[:contents][:value])
      # A device added: the app is loaded again, and the answers are the new app's.
      spare = changed.sub("as: 'gps')", "as: 'gps')\ndevice(Devices::GPS::Ublox::F9, as: 'spare_gps')")
      @client.change(path, spare, version: 3)
      @client.diagnostics_of(path)
      hover = @client.request('textDocument/hover', at(path, spare, 'spare_gps', offset: 1))[:result]
      assert_match(/spare_gps/, hover&.dig(:contents, :value))

      other = file('models/compositions/drive.rb')
      assert_nil @client.request('textDocument/hover', @client.position(other, 0, 0))[:result]
      assert_equal [], @client.request('textDocument/definition', @client.position(other, 0, 0))[:result]
      assert_equal 0, @client.close
    end

    def test_a_file_that_breaks_the_loading_of_another_shows_the_error_where_the_cause_is
      profile = file(PROFILE)
      @client.open(profile)
      assert_equal [], @client.diagnostics_of(profile)

      # The profile requires the composition; the mistake is the composition's.
      composition = file('models/compositions/drive.rb')
      text = File.read(composition)
      @client.open(composition, text.sub("add Devices::Roboteq::CANOpen, as: 'left'",
                                         "add Devices::Roboteq::CANOpne, as: 'left'"))
      diagnostic, = @client.diagnostics_of(composition)
      assert_match(/CANOpne/, diagnostic[:message])
      assert_equal text.lines.index { |l| l.include?("as: 'left'") }, diagnostic[:range][:start][:line]

      @client.change(composition, text)
      assert_equal [], @client.diagnostics_of(composition)
    end

    def test_an_unsaved_configuration_file_and_orogen_spec_are_checked_as_typed
      conf = file('config/orogen/camera_gige::Task.yml')
      text = File.read(conf)
      @client.open(conf, text.sub('frame_rate: 20.0', 'frame_rat: 20.0'))
      diagnostic, = @client.diagnostics_of(conf)
      assert_match(/frame_rat/, diagnostic[:message])
      assert_equal text.lines.index { |l| l.start_with?('frame_rate') }, diagnostic[:range][:start][:line]
      @client.change(conf, text)
      assert_equal [], @client.diagnostics_of(conf)

      spec = file('models/orogen/camera_gige.orogen')
      text = File.read(spec)
      @client.open(spec, text.sub("property 'exposure', 'int', 10_000", "property 'exposure', 'int', 10_000,"))
      diagnostic, = @client.diagnostics_of(spec)
      assert_equal 1, diagnostic[:severity]
      @client.notify('textDocument/didSave', textDocument: { uri: LSP::URI.of(spec) }, text: text)
      assert_equal [], @client.diagnostics_of(spec)
    end

    # A model file that prints, or runs a command that prints: the protocol
    # stays readable (the client checks every header), and what they print
    # is in the server's log.
    def test_what_files_print_goes_to_the_log_not_the_protocol
      path = file('models/services/position.rb')
      text = File.read(path)
      @client.open(path, "puts 'hello'\n$stdout.write('more')\nSTDOUT.puts 'again'\nsystem('echo', 'child')\n#{text}")
      assert_equal [], @client.diagnostics_of(path)
      assert_equal 0, @client.close
      assert_includes @client.stderr, 'hello'
      assert_includes @client.stderr, 'child'
    end

    # A file that exits or recurses forever, a request the server does not
    # answer or cannot read: each is answered, and the server goes on.
    def test_files_that_exit_or_blow_up_and_bad_requests_do_not_stop_the_server
      path = file('models/services/position.rb')
      text = File.read(path)
      @client.open(path, "#{text}\nexit 3\n")
      assert_diagnostic(@client.diagnostics_of(path).first, line: text.lines.size + 1, message: /exit/)
      @client.change(path, "def deep = deep\ndeep\n#{text}")
      assert_diagnostic(@client.diagnostics_of(path).first, line: 0, message: /recursion|stack/)

      unknown = @client.request('textDocument/formatting', textDocument: { uri: LSP::URI.of(path) })
      assert_equal(-32_601, unknown[:error][:code])
      bad = @client.request('textDocument/hover', {})
      assert_nil bad[:result]
      @client.change(path, text)
      assert_equal [], @client.diagnostics_of(path)
      assert_equal 0, @client.close
    end
  end
end
