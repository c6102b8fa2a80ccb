# frozen_string_literal: true

module Syskit
  # `syskit plan` and `syskit diff`, commands of `syskit` (see syskit/cli.rb):
  # a profile's connection plan in one of the RENDERERS' formats, and what
  # changed between two plans (`syskit plan --diff` compares the plan it
  # makes with one written before).
  class CLI < Thor
    # The formats of `syskit plan`, each the name of its renderer
    # (syskit/render/NAME.rb, Render::...), loaded when used.
    RENDERERS = { 'text' => :Text, 'json' => :JSON, 'dot' => :Dot, 'svg' => :Svg }.freeze

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
      Without --app, the app containing the current directory (outside an
      app, the command says so).

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
        profile = find_profile(app, profile_name, command: 'plan')
        note_empty_profile(app, profile)
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
      # A profile with nothing to plan gives an empty plan: said on stderr,
      # at the profile's declaration, rather than printed as if planned.
      def note_empty_profile(app, profile)
        return unless profile.action_names.empty?

        empty = Warning.new("#{profile.name} has no device and no definition: its plan is empty",
                            location: profile.declared_at, hint: "declare the robot's devices in its robot block")
        warn Style.for($stderr).report(empty, app.root)
      end

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

    private

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
  end
end
