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

    # Lists of commands fit 80 columns without cutting a word: every
    # description is there whole.
    def test_command_lists_wrap_descriptions_at_words
      columns = ENV.fetch('THOR_COLUMNS', nil)
      ENV['THOR_COLUMNS'] = '80'
      [%w[help], %w[gen help], %w[bus help]].each do |args|
        out, = run_cli(*args)
        lines = out.lines.map(&:chomp)
        assert(lines.all? { |l| l.size <= 80 }, "syskit #{args.join(' ')}:\n#{out}")
        refute_match(/\.\.\.$/, out)
        klass = { 'help' => CLI, 'gen' => CLI::Gen, 'bus' => CLI::Bus }.fetch(args.first)
        klass.commands.each_value do |command|
          next if command.hidden?

          assert_includes out.split.join(' '), command.description, "syskit #{args.join(' ')}"
        end
      end
      assert_match(/^  syskit bus monitor \[PROFILE\] --interface=INTERFACE\n {42}# watch a live/,
                   run_cli('help').first)
    ensure
      ENV['THOR_COLUMNS'] = columns
    end

    # Rock's Syskit commands say what this gem offers instead; other unknown
    # commands what was meant, as syskit errors are printed.
    def test_unknown_commands
      { %w[instanciate -r gazebo Base.arm_def] =>
          "syskit instanciate is a command of Rock's Syskit, which builds the network of actions in Roby: this gem " \
          "has no runtime\n  hint: syskit plan [PROFILE] [ACTION...] prints the network of a profile or of some of " \
          "its actions (e.g. syskit plan Live::Base gps_dev)\n",
        %w[ide] => "syskit ide is a command of Rock's Syskit, which browses models and networks in a Qt window: this " \
                   "gem has no runtime\n  hint: syskit doc writes the app's models and plans as pages to browse, and " \
                   "syskit plan --format svg draws a plan\n",
        %w[plna] => "unknown command 'syskit plna' (did you mean 'syskit plan'?)\n  hint: syskit help lists the " \
                    "commands\n",
        %w[bus replya] => "unknown command 'syskit bus replya' (did you mean 'syskit bus replay'?)\n  hint: syskit " \
                          "bus help lists the commands\n",
        %w[gen app] => "syskit gen app needs arguments\n  hint: usage: syskit gen app NAME (syskit gen app --help " \
                       "tells more)\n",
        %w[version x] => "syskit version does not take the arguments x\n  hint: usage: syskit version (syskit " \
                         "version --help tells more)\n" }.each do |args, message|
        out, err, status = run_cli(*args)
        assert_equal [1, '', message], [status, out, err], "syskit #{args.join(' ')}"
      end
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
        assert_equal "#{option} takes the seed of a run, an integer, not 'x'\n  hint: e.g. syskit test #{option} 42: " \
                     "minitest prints each run's seed (Run options: --seed N) to run the tests again in the same " \
                     "order\n", err
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
