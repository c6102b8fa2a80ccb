# frozen_string_literal: true

require 'syskit/errors'

module Syskit
  module Test
    # `syskit test` and an app's `rake test`: runs test files as Syskit runs
    # them. The harness (require 'syskit/test': the app loaded, `describe`
    # blocks with Syskit's assertions) is set up before the files are
    # loaded, so that they need no require; minitest's own options
    # (-n/--name, -e/--exclude, -s/--seed, -v/--verbose) go to minitest.
    #
    # `syskit test` and `rake test` run the tests in their own process
    # (#run): the files are loaded by #run_files, then minitest runs at
    # exit, as it does for any minitest file, and its status is the
    # process's.
    class Runner
      # minitest's options, and whether each takes a value.
      MINITEST_OPTIONS = { '-n' => true, '--name' => true, '-e' => true, '--exclude' => true,
                           '-s' => true, '--seed' => true, '-v' => false, '--verbose' => false }.freeze

      Arguments = Struct.new(:files, :minitest, :app)

      # Splits `syskit test` arguments into test files, minitest options and
      # --app (which may come after a minitest option); raises a Syskit
      # error for an option neither knows.
      def self.parse(args)
        files = []
        minitest = []
        app = nil
        args = args.dup
        until args.empty?
          arg = args.shift
          name, value = arg.split('=', 2)
          if name == '--app'
            app = value || args.shift
          elsif MINITEST_OPTIONS.key?(name)
            minitest << name
            minitest << option_value(name, value || args.shift) if MINITEST_OPTIONS[name]
          elsif arg.start_with?('-') && arg != '-'
            raise unknown_option(arg)
          else
            files << arg
          end
        end
        Arguments.new(files, minitest, app)
      end

      # The value of a minitest option, checked here: minitest would stop
      # with a backtrace (-s abc), or take the next option as the value
      # (-n --app dir).
      def self.option_value(name, value)
        if %w[-s --seed].include?(name)
          return value if value && Integer(value, exception: false)

          raise Error.new("#{name} takes the seed of a run, an integer#{", not '#{value}'" if value}",
                          hint: "e.g. syskit test #{name} 42: minitest prints each run's seed (Run options: " \
                                '--seed N) to run the tests again in the same order')
        end
        return value if value && !value.start_with?('-')

        what = %w[-n --name].include?(name) ? 'runs' : 'leaves out'
        raise Error.new("#{name} needs a pattern#{" before '#{value}'" if value}",
                        hint: "e.g. syskit test #{name} /configure/ #{what} the tests whose name matches " \
                              "(#{name} test_name: that test); quote a pattern with spaces")
      end

      def self.unknown_option(arg)
        Error.new("syskit test does not know the option '#{arg}'",
                  hint: "minitest's options: -n/--name PATTERN, -e/--exclude PATTERN, -s/--seed N, -v/--verbose; " \
                        'syskit test --help lists them all')
      end

      # The test files: +files+ (relative to +pwd+), else every
      # test/**/test_*.rb of the app. A file that does not exist is a
      # located error.
      def self.test_files(root, files, pwd: Dir.pwd)
        return Dir[File.join(root, 'test', '**', 'test_*.rb')] if files.empty?

        files.map do |file|
          path = File.expand_path(file, pwd)
          next path if File.file?(path)

          raise FileLoadError.new(
            "no test file '#{file}'",
            location: Location.new(path, 1),
            hint: "give the path of a test file (from the current directory), e.g. #{Location.new(
              File.join(root, 'test', 'profiles', 'test_base.rb'), 1
            ).relative_path(Dir.pwd)}"
          )
        end
      end

      # Loads the tests of the app at +root+ in this process, from the app's
      # directory; minitest runs them when the process exits.
      def self.run(root, files, minitest)
        ENV['SYSKIT_APP'] = root
        Dir.chdir(root)
        run_files([*files, '--', *minitest])
      end

      # Sets the harness up, loads the files given before '--', and leaves
      # minitest the options given after it.
      def self.run_files(argv)
        separator = argv.index('--') || argv.size
        files = argv[0...separator]
        ARGV.replace(argv[(separator + 1)..] || [])
        require 'syskit/test'
        files.each { |file| load_test_file(file) }
      end

      # Loads a test file; what it raises while being loaded (a syntax
      # error, a typo at its top level, a library that is not installed, an
      # exit that would leave the next files unloaded) is reported at its
      # line, on stderr (after the app's own problems, see Test.app) and as
      # a failing test of its own, and the other files' tests run.
      def self.load_test_file(path)
        require path
      rescue Syskit::Error, ScriptError, StandardError, SystemExit => e
        error = UserCode.translate(e, path: path, root: Test.app.root)
        report = error.report(Dir.pwd)
        warn report
        LoadProblems.test_files << report
        Class.new(Minitest::Test) do
          define_singleton_method(:name) { "#{Location.new(path, nil).relative_path(Dir.pwd)} (loading)" }
          define_method(:test_the_file_loads) { flunk report }
        end
      end
    end
  end
end
