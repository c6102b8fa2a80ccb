# frozen_string_literal: true

module Syskit
  # `syskit test`, a command of `syskit` (see syskit/cli.rb): an app's tests,
  # run by Test::Runner.
  class CLI < Thor
    desc 'test [OPTIONS] [FILES...]', "run an app's tests (every test/**/test_*.rb by default)"
    long_desc <<~TEXT
      Runs the app's minitest files with syskit's test harness set up first,
      so test files need no require (as with Syskit's own runner). Options
      after the command go to minitest: -n/--name PATTERN (run the tests
      whose name matches), -e/--exclude PATTERN, -s/--seed N, -v/--verbose.
      Exits with minitest's status.

      Examples: syskit test test/orogen/test_canbus.rb -n /watch/
                syskit test --app ~/dev/awesome_robot -v
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    stop_on_unknown_option! :test
    def test(*args)
      reporting_errors(-> { Dir.pwd }) do
        parsed = Test::Runner.parse(args)
        root = parsed.app ? App.check_root(parsed.app) : app_root
        Test::Runner.run(root, Test::Runner.test_files(root, parsed.files), parsed.minitest)
      end
    end
  end
end
