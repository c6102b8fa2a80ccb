# frozen_string_literal: true

require 'helper'
require 'open3'
require 'tmpdir'

module Syskit
  # The gem as users get it: built with `gem build`, installed with `gem
  # install` in a GEM_HOME of its own, run from outside this tree; and a
  # new app made by either, whose tests run with `rake test` and `bundle
  # exec rake test`, as `gen app` tells.
  class TestInstalledGem < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!
    extend SelfTest::Long

    def setup
      @tmp = Dir.mktmpdir('syskit-gem')
    end

    def teardown
      FileUtils.rm_rf(@tmp)
    end

    def test_the_installed_gem_runs_outside_any_app_and_its_new_app_runs_rake_test
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
      assert_app_tests_run(app)
      out, = run!(syskit, 'check', chdir: app)
      assert_equal "Bot: 0 error(s), 0 warning(s)\n", out
      assert_site_has_the_guides(syskit, app)
    end

    # Made from a checkout, an app names it in its Gemfile: its tests run
    # with no SYSKIT_PATH and no syskit installed, with or without Bundler.
    def test_a_new_app_made_from_a_checkout_runs_its_tests_with_that_checkout
      out, = run!(RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), 'gen', 'app', 'my-bot', chdir: @tmp)
      assert_match(%r{^MyBot is in my-bot/; next: cd my-bot && rake test$}, out)
      app = File.join(@tmp, 'my-bot')
      assert_includes File.read(File.join(app, 'Gemfile')), "path: ENV.fetch('SYSKIT_PATH', #{GEM_ROOT.inspect})"
      assert_app_tests_run(app)
    end

    private

    # The installed gem ships its guides: the site has a page of each,
    # listed in the README's order.
    def assert_site_has_the_guides(syskit, app)
      run!(syskit, 'doc', chdir: app)
      guides = Dir.glob('*.md', base: File.join(GEM_ROOT, 'doc', 'guides')).map { |f| f.sub(/\.md\z/, '.html') }
      assert_equal guides.sort, Dir.children(File.join(app, 'doc', 'site', 'guides')).sort
      index = File.read(File.join(app, 'doc', 'site', 'index.html'))
      assert_match %r{<section class="kind" id="guides">\n<h2>Guides .*href="guides/devices-and-buses\.html"}m, index
    end

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

    # `rake test` and `bundle exec rake test`, as the new app's README says:
    # the profile tests run, and fail until the Base profile has something
    # to check, saying so.
    def assert_app_tests_run(app)
      [%w[rake test], %w[bundle exec rake test]].each do |command|
        out, _err, status = run_command(*command, chdir: app)
        refute status.success?, command.join(' ')
        assert_match(/^4 runs, .* 4 failures, 0 errors/, out, command.join(' '))
        assert_equal 4, out.scan('Base has no device and no definition, so there is nothing to check').size, out
      end
    end

    # The environment of a shell outside this project's Bundler setup, with
    # the temporary GEM_HOME first.
    def env
      base = defined?(Bundler) ? Bundler.unbundled_env : ENV.to_h
      base = base.except('SYSKIT_PATH', 'RUBYLIB')
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
