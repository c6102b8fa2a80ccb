# frozen_string_literal: true

require_relative 'editor_helper'

module Syskit
  # `syskit lsp` with a real editor: Debian's Neovim, headless, configured
  # as the editor guide says, on a copy of the example app whose profile
  # has a mistake; the diagnostics it shows are read back from a file.
  class TestLSPNeovim < Minitest::Test
    include SelfTest::EditorHelper

    NVIM = SelfTest::EditorHelper.find_executable('nvim')
    SCRIPT = File.expand_path('neovim_diagnostics.lua', __dir__)
    # The editor guide's configuration for Neovim 0.7 and later.
    GUIDE_SNIPPET = /^```lua\n(-- syskit lsp for Ruby, YAML and .orogen files \(Neovim 0.7 and later\)\n.*?)^```/m

    def setup
      skip 'Neovim (nvim) is not installed: the test of syskit lsp in a real editor is skipped' unless NVIM
      super
    end

    def test_neovim_shows_the_mistake_of_a_profile_at_its_line
      result = diagnostics_in_neovim(profile_with_a_mistake)
      assert result['published'], 'Neovim got no diagnostics'
      diagnostic, = result['diagnostics']
      assert_equal mistake_line, diagnostic['line']
      assert_equal 'syskit', diagnostic['source']
      assert_equal 1, diagnostic['severity'] # vim.diagnostic.severity.ERROR
      assert_match MISTAKE, diagnostic['message']
      # Where the guide says the hint is.
      assert_equal "hint: did you mean 'AwesomeRobot::Devices::GPS::Ublox::F9'?", diagnostic['hint']
    end

    private

    # Neovim with the editor guide's configuration for Neovim 0.7 as its
    # init.lua.
    def diagnostics_in_neovim(file)
      out = File.join(@dir, 'diagnostics.json')
      init = guide_configuration(GUIDE_SNIPPET, 'init.lua')
      _, err, status = Open3.capture3(editor_env, NVIM, '--headless', '-u', init,
                                      '--cmd', "let g:syskit_lsp_test = ['#{out}', '#{file}']",
                                      '-c', "luafile #{SCRIPT}", chdir: @dir, unsetenv_others: true)
      assert File.file?(out), "Neovim wrote no result (status #{status.exitstatus}): #{err}"
      JSON.parse(File.read(out))
    end
  end
end
