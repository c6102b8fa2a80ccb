# frozen_string_literal: true

require_relative 'editor_helper'

module Syskit
  # `syskit lsp` in Emacs: Debian's Emacs with eglot, in batch mode, with
  # the editor guide's configuration, on a copy of the example app whose
  # profile has a mistake; the diagnostics Flymake shows are read back.
  class TestLSPEmacs < Minitest::Test
    include SelfTest::EditorHelper

    EMACS = SelfTest::EditorHelper.find_executable('emacs')
    SCRIPT = File.expand_path('emacs_diagnostics.el', __dir__)
    # The editor guide's configuration for eglot.
    GUIDE_SNIPPET = /^```elisp\n(;; syskit lsp for Ruby and YAML files.*?)^```/m

    def setup
      skip 'Emacs is not installed: the test of syskit lsp in Emacs is skipped' unless EMACS
      skip 'Emacs has no eglot (Debian: apt-get install elpa-eglot): the test of syskit lsp in Emacs is skipped' \
        unless emacs_has?('eglot')
      super
    end

    def test_emacs_shows_the_mistake_of_a_profile_at_its_line
      result = diagnostics_in_emacs(profile_with_a_mistake)
      assert_equal 'live', result['server'], 'eglot did not start syskit lsp for the profile'
      diagnostic, = result['diagnostics']
      refute_nil diagnostic, 'Flymake shows no diagnostic'
      assert_equal mistake_line, diagnostic['line']
      assert_equal 'eglot-error', diagnostic['type']
      assert_match(/\Asyskit \[FileLoadError\]: #{MISTAKE.source}/, diagnostic['text'])
      # eglot does not show related information: the hint is in the text.
      assert_match(/\nhint: did you mean 'AwesomeRobot::Devices::GPS::Ublox::F9'\?\z/, diagnostic['text'])
    end

    # The guide's entry names yaml-mode, which Emacs 28 does not have: with
    # it (Debian's elpa-yaml-mode), a configuration file has its diagnostics.
    def test_emacs_with_yaml_mode_shows_the_mistake_of_a_configuration_file
      skip 'Emacs has no yaml-mode (Debian: elpa-yaml-mode): its YAML test is skipped' unless emacs_has?('yaml-mode')
      path = File.join(example_copy, 'config', 'orogen', 'canbus::Task.yml')
      text = File.read(path)
      File.write(path, text.sub('deviceType:', 'deviceTyp:'))
      result = diagnostics_in_emacs(path)
      assert_equal 'orogen', result['server'], 'eglot did not start syskit lsp for the configuration file'
      diagnostic, = result['diagnostics']
      refute_nil diagnostic, 'Flymake shows no diagnostic'
      assert_equal text.lines.index { |l| l.start_with?('deviceType:') }, diagnostic['line']
      assert_match(/\Asyskit \[ConfigurationError\]: canbus::Task has no property 'deviceTyp'.*\nhint: /m,
                   diagnostic['text'])
    end

    private

    # Whether Emacs (with Debian's site files: -q skips only the user's
    # init file) can load +feature+.
    def emacs_has?(feature)
      Open3.capture3(EMACS, '--batch', '-q', '--eval', "(require '#{feature})")[2].success?
    end

    def diagnostics_in_emacs(file)
      out = File.join(@dir, 'diagnostics.json')
      init = guide_configuration(GUIDE_SNIPPET, 'init.el')
      # Packages (Debian's elpa-*) are activated before init.el, as Emacs
      # does when it starts for a user; batch mode does not.
      _, err, status = Open3.capture3(editor_env, EMACS, '--batch', '-q', '--eval', '(package-activate-all)',
                                      '-l', init, '-l', SCRIPT, file, out, chdir: @dir, unsetenv_others: true)
      assert File.file?(out), "Emacs wrote no result (status #{status.exitstatus}): #{err}"
      JSON.parse(File.read(out))
    end
  end
end
