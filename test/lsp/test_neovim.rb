# frozen_string_literal: true

require_relative '../helper'
require 'json'

module Syskit
  # `syskit lsp` with a real editor: Debian's Neovim, headless, configured
  # as the editor guide says, on a copy of the example app whose profile
  # has a mistake; the diagnostics it shows are read back from a file.
  class TestLSPNeovim < Minitest::Test
    include SelfTest

    NVIM = ENV['PATH'].to_s.split(File::PATH_SEPARATOR).map { |dir| File.join(dir, 'nvim') }
                      .find { |path| File.executable?(path) }
    SCRIPT = File.expand_path('neovim_diagnostics.lua', __dir__)
    # The editor guide's configuration for Neovim 0.7 and later.
    GUIDE_SNIPPET = /^```lua\n(-- syskit lsp for Ruby, YAML and .orogen files \(Neovim 0.7 and later\)\n.*?)^```/m

    def setup
      skip 'Neovim (nvim) is not installed: the test of syskit lsp in a real editor is skipped' unless NVIM
      @dir = Dir.mktmpdir('syskit-nvim')
    end

    def teardown
      FileUtils.rm_rf(@dir) if @dir
    end

    def test_neovim_shows_the_mistake_of_a_profile_at_its_line
      root = File.join(@dir, 'awesome_robot')
      FileUtils.cp_r(File.join(GEM_ROOT, 'examples', 'awesome_robot'), @dir)
      profile = File.join(root, 'models', 'profiles', 'live', 'base.rb')
      text = File.read(profile)
      File.write(profile, text.sub('Ublox::F9', 'Ublox::F8'))

      result = diagnostics_in_neovim(profile)
      assert result['published'], 'Neovim got no diagnostics'
      diagnostic, = result['diagnostics']
      assert_equal text.lines.index { |l| l.include?('Ublox::F9') }, diagnostic['line']
      assert_equal 'syskit', diagnostic['source']
      assert_equal 1, diagnostic['severity'] # vim.diagnostic.severity.ERROR
      assert_match(/uninitialized constant .*Ublox::F8/, diagnostic['message'])
      # Where the guide says the hint is.
      assert_equal "hint: did you mean 'AwesomeRobot::Devices::GPS::Ublox::F9'?", diagnostic['hint']
    end

    private

    # Neovim with the editor guide's configuration for Neovim 0.7 as its
    # init.lua, and `syskit` on its PATH (this checkout's bin/syskit).
    def diagnostics_in_neovim(file)
      out = File.join(@dir, 'diagnostics.json')
      env = SelfTest.child_env.merge('HOME' => @dir, 'PATH' => "#{syskit_on_path}:#{ENV.fetch('PATH', '')}")
      _, err, status = Open3.capture3(env, NVIM, '--headless', '-u', guide_configuration,
                                      '--cmd', "let g:syskit_lsp_test = ['#{out}', '#{file}']",
                                      '-c', "luafile #{SCRIPT}", chdir: @dir, unsetenv_others: true)
      assert File.file?(out), "Neovim wrote no result (status #{status.exitstatus}): #{err}"
      JSON.parse(File.read(out))
    end

    def guide_configuration
      snippet = File.read(File.join(GEM_ROOT, 'doc', 'guides', 'editor.md'))[GUIDE_SNIPPET, 1]
      assert snippet, 'the editor guide has no Neovim 0.7 configuration'
      path = File.join(@dir, 'init.lua')
      File.write(path, snippet)
      path
    end

    def syskit_on_path
      bin = File.join(@dir, 'bin')
      FileUtils.mkdir_p(bin)
      syskit = File.join(GEM_ROOT, 'bin', 'syskit')
      File.write(File.join(bin, 'syskit'), "#!/bin/sh\nexec '#{RbConfig.ruby}' '#{syskit}' \"$@\"\n")
      File.chmod(0o755, File.join(bin, 'syskit'))
      bin
    end
  end
end
