# frozen_string_literal: true

# Only what every command needs is loaded here: the command classes, their
# descriptions and options. What a command does (the model layer, the
# renderers, the generators...) is loaded when it runs (see Support and
# LIBRARIES): `syskit help` and `syskit --version` answer without it.
require 'thor'
require 'syskit/version'
require 'syskit/cli/support'
require 'syskit/cli/command_line'
require 'syskit/cli/style'
require 'syskit/cli/help'
require 'syskit/cli/terminal_width'

module Syskit
  # `syskit`: thin Thor commands that parse options, call one function of the
  # library and print its result.
  class CLI < Thor
    # The formats of `syskit plan`, each the name of its renderer
    # (syskit/render/NAME.rb, Render::...), loaded when used.
    RENDERERS = { 'text' => :Text, 'json' => :JSON, 'dot' => :Dot, 'svg' => :Svg }.freeze

    # What each command loads before it runs (see Help#libraries); the
    # others load the model layer, syskit, and the rest as they go. `gen`
    # and `bus` are groups: their commands say what they need.
    LIBRARIES = {
      'version' => [], 'gen' => [], 'bus' => [],
      'diff' => %w[syskit syskit/cli/plan_files], 'check' => %w[syskit syskit/check set],
      'doc' => %w[syskit syskit/doc], 'test' => %w[syskit syskit/test/runner]
    }.freeze

    def self.libraries(command_name)
      LIBRARIES.fetch(command_name) { super }
    end

    def self.exit_on_failure?
      true
    end

    extend Help

    # Usage lines say syskit, however the command was started.
    def self.basename
      'syskit'
    end

    # The command line as users type it (see CommandLine), errors as
    # syskit prints them (see Shell).
    def self.start(given_args = ARGV, config = {})
      config[:shell] ||= Shell.new
      # Thor stops with a backtrace on an argument that is not UTF-8.
      bad = given_args.find { |arg| !Printable.utf8?(arg) }
      return CommandLine.not_text(bad) if bad

      super(CommandLine.normalize(given_args), config)
    end

    # Options every command takes, said once under the list of commands.
    COMMON_OPTIONS = <<~TEXT
      Every command takes --help (-h), and --trace: errors with Ruby's backtrace.
      syskit --version (-v) prints the version.
    TEXT

    # `syskit help`: the commands, then the options every command takes.
    def self.help(shell, subcommand = false) # rubocop:disable Style/OptionalBooleanParameter -- Thor's signature
      list = printable_commands(true, subcommand)
      Thor::Util.thor_classes_in(self).each { |klass| list += klass.printable_commands(false) }
      shell.say 'Commands:'
      shell.print_table(list.sort_by(&:first), indent: 2, truncate: true)
      shell.say
      shell.say COMMON_OPTIONS
    end

    include Support

    # Options are checked: a typo is an error, not a profile name. `syskit
    # test` hands the options it does not know to minitest.
    check_unknown_options!(except: %i[test])

    # --trace is accepted everywhere; the help says so once, in each
    # command's description, rather than as Thor's --[no-,skip-]trace.
    class_option :trace, type: :boolean, default: false, hide: true, desc: 'show the backtrace of errors'

    desc 'version', 'print the version (also: syskit --version, syskit -v)'
    def version
      $stdout.write(Syskit.version_text)
    end

    desc 'plan [PROFILE] [ACTION...]', 'print the connection plan of a profile'
    long_desc <<~TEXT
      Generates the network of PROFILE (all its devices and definitions, or
      the given actions, e.g. gps_dev or arm_control_def) on a robot and
      prints the plan: compositions, tasks, deployments, configuration,
      ports, connections and the configure/start order. When a profile's
      definitions cannot all run at once but each plans on its own, the plan
      is its devices' and a warning says which definitions to plan one at a
      time.

      PROFILE is the profile's name or its end (Live::Base), or the path form
      of gen profile (live/base); Base is Profiles::Base when there is one.
      Without PROFILE, the app's first profile.
      Without --app, the app containing the current directory, else (in a
      checkout of syskit) the example app.

      --format svg draws the dot graph with graphviz (which must be installed).
      The picture shows the ports the plan connects; --all-ports shows every
      port.

      --diff OLD.json prints what changed since the plan in OLD.json (written
      by --format json) instead of the plan: see syskit diff.

      Example: syskit plan Live::Base temperature_sensor_dev --format json

      Example: syskit plan Live::Base --diff plan-before.json
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    method_option :robot, type: :string, default: 'default', desc: 'the robot configuration (config/robots/NAME.rb)'
    method_option :format, type: :string, default: 'text', enum: RENDERERS.keys, desc: 'output format'
    method_option :all_ports, type: :boolean, default: false, desc: 'dot and svg: draw unconnected ports too'
    method_option :diff, type: :string, banner: 'OLD.json', desc: 'print what changed since the plan in OLD.json'
    method_option :exit_code, type: :boolean, default: false, desc: 'with --diff: exit status 1 when the plans differ'
    def plan(profile_name = nil, *actions)
      with_app(robots: [options[:robot]]) do |app|
        old = read_old_plan
        profile = find_profile(app, profile_name)
        result = plan_actions(app, profile, actions)
        if old
          print_diff(old, PlanFiles.plain(result.plan), new_name: "syskit plan #{[profile.name, *actions].join(' ')}")
        else
          picture = %w[dot svg].include?(options[:format]) ? { all_ports: options[:all_ports] } : {}
          renderer(options[:format]).write(result.plan, $stdout, **picture)
        end
        note_warnings(app)
        note_missed_deadlines(profile)
        exit(1) if @plans_differ
      end
    end

    no_commands do
      # The renderer of +format+ (a key of RENDERERS).
      def renderer(format)
        require_once "syskit/render/#{format}"
        Render.const_get(RENDERERS.fetch(format))
      end

      # A profile planned whole whose definitions cannot all run at once
      # prints its devices' plan (see Network::ProfilePlan); when one of
      # them does not plan on its own either, the error says which to plan.
      def plan_actions(app, profile, actions)
        robot = options[:robot]
        return Network::Generator.plan_profile(app, profile, actions: actions, robot: robot) unless actions.empty?

        result = Network::ProfilePlan.new(app, profile, robot: robot)
        warn Style.for($stderr).report(result.apart_warning, app.root) if result.apart?
        result
      rescue Syskit::Error => e
        definitions = profile.definitions.keys
        raise e unless actions.empty? && definitions.size > 1

        raise ErrorList, [e, Warning.new(
          "the #{definitions.size} definitions of #{profile.name} were planned together, with its devices",
          hint: "plan one at a time: syskit plan #{profile.name} #{definitions.first}_def"
        )]
      end
    end

    desc 'diff OLD.json NEW.json', 'what changed between two plans written by syskit plan --format json'
    long_desc <<~TEXT
      Compares two plans, as syskit plan --format json writes them, for a
      review before the change meets hardware: per list of the plan (tasks,
      devices, connections, order, buses), the entries added (+), removed
      (-) and changed (~, each value that changed: deployment, configuration
      properties and conf sections, ports, policies, bus frames...), and the
      steps that moved in the start order. Where things are declared
      (declared_at) is not compared. --format json gives the same for
      programs. Exit status 0, or with --exit-code 1 when the plans differ.

      Example: git show main:plan.json > old.json && syskit diff old.json plan.json
    TEXT
    method_option :format, type: :string, default: 'text', enum: %w[text json], desc: 'output format'
    method_option :exit_code, type: :boolean, default: false, desc: 'exit status 1 when the plans differ'
    def diff(old_path, new_path)
      reporting_errors(-> { Dir.pwd }) do
        old = PlanFiles.read(old_path)
        print_diff(old, PlanFiles.read(new_path), old_name: old_path, new_name: new_path)
      end
      exit(1) if @plans_differ
    end

    desc 'check', 'load an app, generate every profile on every robot, report every problem'
    long_desc <<~TEXT
      Reports all the problems found (not only the first), grouped by file,
      and exits with status 1 if there is any error. Overlapping CAN filters
      are warnings; --strict makes them errors.

      Example: syskit check --app ~/dev/awesome_robot --format json
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    method_option :strict, type: :boolean, default: false, desc: 'treat warnings as errors'
    method_option :format, type: :string, default: 'text', enum: %w[text json], desc: 'output format'
    def check
      with_app(load: false) do |app|
        report = Check.new(app).run
        report.strict! if options[:strict]
        print_check(app, report)
        exit(1) if report.errors.any?
      end
    end

    desc 'doc', "write the app's models and plans as a static HTML site"
    long_desc <<~TEXT
      Writes an index of every device model, bus model, data service, task
      library, task model and profile of the app (and of the bundles it
      uses), a page for each, and each profile's connection plan on the
      robot, drawn with graphviz when it is installed. The site works
      offline, from file://; the same app gives the same files.

      --output defaults to doc/site in the app; a directory there is only
      replaced if syskit doc wrote it.

      Example: syskit doc --app ~/dev/awesome_robot --output /tmp/site
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    method_option :robot, type: :string, default: 'default', desc: 'the robot configuration the plans are made for'
    method_option :output, type: :string, desc: 'where to write the site (default: doc/site in the app)'
    def doc
      # Every task library of the app is documented, not only those its
      # profiles use (as syskit check loads them).
      with_app(load: false) do |app|
        app.load!(robots: [options[:robot]], everything: true)
        app.robot_config(options[:robot])
        output = options[:output] ? File.expand_path(options[:output]) : File.join(app.root, 'doc', 'site')
        result = Doc.build(app, output: output, robot: options[:robot])
        report_site(result)
        note_warnings(app)
      end
    end

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

    private

    # What syskit doc wrote, and what the site could not show.
    def report_site(result)
      style = Style.for($stderr)
      result.unplanned.each do |profile, errors|
        warn style.warning("#{profile.name} could not be planned (#{errors.first.message}): its page says why")
      end
      warn style.warning('graphviz is not installed: plans are listed, not drawn (install graphviz)') unless result.dot
      puts "wrote #{Naming.count(result.pages, 'page')} to #{result.output}"
      puts "open #{File.join(result.output, 'index.html')}"
    end

    # The plan of --diff, read before the app is generated; a format that
    # is not text or JSON has no diff.
    def read_old_plan
      return unless options[:diff]

      require_once 'syskit/cli/plan_files'
      unless %w[text json].include?(options[:format])
        raise Error.new("--diff prints the difference as text or json, not #{options[:format]}",
                        hint: 'leave out --format, or give --format json')
      end
      PlanFiles.read(options[:diff])
    end

    # Prints the diff of two plan documents; remembers whether they differ
    # for --exit-code.
    def print_diff(old, new, new_name:, old_name: options[:diff])
      diff, text = PlanFiles.render(old, new, options[:format], old_name: old_name, new_name: new_name)
      $stdout.write(text)
      @plans_differ = options[:exit_code] && !diff.empty?
    end

    # Warnings do not stop a plan (constructs of Rock files this gem does
    # not model, ...): one line on stderr says there are some.
    def note_warnings(app)
      count = app.problems.grep(Warning).size
      return unless count.positive?

      warn Style.for($stderr).warning("#{Naming.count(count, 'warning')} while loading (syskit check lists them)")
    end

    # A plan whose CAN frames can miss their deadline is still printed
    # (syskit check reports it as an error): one line per bus on stderr
    # says so and which command shows why.
    def note_missed_deadlines(profile)
      require_once 'syskit/cli/bus_timing'
      style = Style.for($stderr)
      BusTiming.missed_deadlines(profile).each do |bus, missed, total|
        warn style.warning("#{bus}: #{Naming.count(missed, 'frame')} of #{total} can miss " \
                           "#{missed == 1 ? 'its' : 'their'} deadline " \
                           "(syskit bus timing #{profile.name} --bus #{bus.name} shows which)")
      end
    end

    def print_check(app, report)
      return print_check_json(app, report) if options[:format] == 'json'

      # Files in the order their first problem was found, which puts the
      # cause before what follows from it; lines in order within a file.
      groups = report.problems.group_by { |p| p.location&.relative_path(app.root).to_s }
      hints = Set.new
      groups.each_with_index do |(_file, problems), i|
        puts if i.positive?
        print_problems(app, problems, hints)
      end
      puts "#{app.name}: #{report.errors.size} error(s), #{report.warnings.size} warning(s)"
    end

    # The problems of one file, in line order. A warning's hint is given
    # once, under the first warning of its kind (+hints+: those given).
    def print_problems(app, problems, hints)
      style = Style.for($stdout)
      problems.sort_by { |p| p.location&.lineno.to_i }.each do |p|
        p = p.without_hint if p.is_a?(Warning) && p.hint && !hints.add?(p.hint)
        puts style.report(p, app.root)
        puts((p.backtrace || []).map { |l| "    #{l}" }) if trace?
      end
    end

    def print_check_json(app, report)
      require_once 'json'
      puts ::JSON.pretty_generate('app' => app.name, 'errors' => report.errors.size,
                                  'warnings' => report.warnings.size,
                                  'problems' => report.problems.map { |p| p.to_h(app.root) })
    end
  end
end
require 'syskit/cli/bus'
require 'syskit/cli/gen'
