# frozen_string_literal: true

require 'helper'

module Syskit
  # The command line as a new user tries it: help and version everywhere,
  # options checked, --app that is not an app.
  class TestCommandLine < Minitest::Test
    EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')

    def test_every_command_answers_help_and_h
      [%w[plan --help], %w[check -h], %w[test --help], %w[version --help], %w[gen dev --help], %w[gen app -h],
       %w[bus timing --help], %w[bus replay -h]].each do |args|
        out, err, status = run_cli(*args)
        assert_equal 0, status, "syskit #{args.join(' ')}: #{err}"
        assert_match(/^Usage:\n  syskit #{args.first}/, out, "syskit #{args.join(' ')}")
      end
    end

    def test_version_and_v_print_the_version
      %w[--version -v version].each do |arg|
        out, _, status = run_cli(arg)
        assert_equal [0, "syskit #{VERSION}\n"], [status, out.lines.first], arg
      end
    end

    def test_the_help_shows_syskits_commands_only
      out, = run_cli('help')
      refute_match(/syskit tree|skip-trace|no-trace/, out)
      assert_match(/^Every command takes --help \(-h\), and --trace/, out)
      [%w[gen --help], %w[bus --help], %w[gen app --help], %w[check --help]].each do |args|
        out, = run_cli(*args)
        refute_match(/ tree|--skip-|--no-/, out, "syskit #{args.join(' ')}")
      end
      assert_match(/^  \[--dry-run\] +# list the files/, run_cli('gen', '--help').first)
    end

    def test_unknown_options_are_refused_as_options
      [%w[plan --bogus], %w[check --strickt], %w[gen dev gps --forse], %w[bus timing Base --buss can0]].each do |args|
        out, err, status = run_cli(*args, '--app', EXAMPLE)
        assert_equal 1, status, "syskit #{args.join(' ')}"
        assert_empty out
        assert_match(/\Aunknown option '--\w+'\n  hint: /, err)
      end
    end

    # syskit test reads minitest's options itself (they are not unknown
    # options), and a seed minitest would refuse with a backtrace is one
    # message.
    def test_minitest_options_still_reach_syskit_test
      %w[--seed -s].each do |option|
        out, err, status = run_cli('test', option, 'x', '--app', EXAMPLE)
        assert_equal [1, ''], [status, out]
        assert_equal "#{option} takes an integer, got 'x'\n  hint: give the seed minitest printed " \
                     "(Run options: --seed 1234), e.g. #{option} 1234\n", err
      end
    end

    def test_a_rock_bundle_of_configuration_files_only_is_an_app
      root = write_app({ 'config/bundle.yml' => "name: rosa\n",
                         'config/orogen/canbus::Task.yml' => "--- name:default\ndeviceType: SOCKET\n" }, name: 'rosa')
      FileUtils.rm_rf(File.join(root, 'models')) # write_app makes one
      out, err, status = run_cli('check', '--app', root)
      assert_equal [0, "Rosa: 0 error(s), 0 warning(s)\n"], [status, out], err
    end

    def test_an_app_path_that_is_not_an_app
      { '/nonexistent/app' => /there is no such directory/, File.join(EXAMPLE, 'Rakefile') => /it is a file/,
        File.join(EXAMPLE, 'models') => /it is inside the app at #{EXAMPLE}/ }.each do |path, why|
        %w[check plan].each do |command|
          out, err, status = run_cli(command, '--app', path)
          assert_equal 1, status, "#{command} --app #{path}"
          assert_empty out
          assert_match(/\A'#{Regexp.escape(path)}' is not an app: /, err)
          assert_match why, err
        end
      end
    end
  end
end
