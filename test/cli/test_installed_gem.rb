# frozen_string_literal: true

require 'helper'
require 'open3'
require 'tmpdir'

module Syskit
  # The gem as users get it: built with `gem build`, installed with `gem
  # install` in a GEM_HOME of its own, run from outside this tree; and a
  # new app run from a checkout through Bundler, as `gen app` tells.
  class TestInstalledGem < Minitest::Test
    def setup
      @tmp = Dir.mktmpdir('syskit-gem')
    end

    def teardown
      FileUtils.rm_rf(@tmp)
    end

    def test_the_installed_gem_runs_outside_any_app_and_its_new_app_passes_rake_test
      syskit = install_gem
      work = File.join(@tmp, 'work')
      FileUtils.mkdir_p(work)

      out, = run!(syskit, 'version', chdir: work)
      assert_match(/\Asyskit #{Regexp.escape(VERSION)}\n.*not Rock's Syskit, from #{Regexp.escape(@tmp)}/, out)

      # No example app in an installed gem: outside an app, plan says so.
      out, err, status = run_command(syskit, 'plan', chdir: work)
      assert_equal [1, ''], [status.exitstatus, out]
      assert_match(/\A#{Regexp.escape(work)} is not in a Syskit app\n  hint: /, err)

      out, = run!(syskit, 'gen', 'app', 'bot', chdir: work)
      assert_match(%r{^Bot is in bot/; next: cd bot && rake test$}, out)
      app = File.join(work, 'bot')
      refute_includes File.read(File.join(app, 'Gemfile')), GEM_ROOT
      out, = run!('rake', 'test', chdir: app)
      assert_match(/^4 runs, .* 0 failures, 0 errors/, out)
      out, = run!(syskit, 'check', chdir: app)
      assert_equal "Bot: 0 error(s), 0 warning(s)\n", out
    end

    def test_a_new_app_runs_its_tests_with_a_checkout_through_bundler
      out, = run!(RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), 'gen', 'app', 'bot', chdir: @tmp)
      command = out[/next: (.*)$/, 1]
      assert_equal "cd bot && SYSKIT_PATH=#{GEM_ROOT} bundle exec rake test", command
      out, = run!('sh', '-c', command, chdir: @tmp)
      assert_match(/^4 runs, .* 0 failures, 0 errors/, out)
    end

    private

    # Builds the gem from this tree and installs it in a GEM_HOME of its
    # own (its dependencies come from the gems already installed); returns
    # the path of its executable.
    def install_gem
      gem_file = File.join(@tmp, 'syskit.gem')
      run!('gem', 'build', File.join(GEM_ROOT, 'syskit.gemspec'), '-o', gem_file, chdir: GEM_ROOT)
      run!('gem', 'install', '--local', '--no-document', gem_file, chdir: @tmp)
      File.join(gem_home, 'bin', 'syskit')
    end

    def gem_home
      File.join(@tmp, 'gem_home')
    end

    # The environment of a shell outside this project's Bundler setup, with
    # the temporary GEM_HOME first.
    def env
      base = defined?(Bundler) ? Bundler.unbundled_env : ENV.to_h
      base.merge('GEM_HOME' => gem_home, 'GEM_PATH' => [gem_home, *Gem.path].join(File::PATH_SEPARATOR),
                 'PATH' => [File.join(gem_home, 'bin'), base['PATH']].join(File::PATH_SEPARATOR),
                 'NO_COLOR' => '1')
    end

    def run_command(*command, chdir:)
      Open3.capture3(env, *command, chdir: chdir, unsetenv_others: true)
    end

    def run!(*command, chdir:)
      out, err, status = run_command(*command, chdir: chdir)
      assert status.success?, "#{command.join(' ')} failed:\n#{out}\n#{err}"
      [out, err]
    end
  end
end
