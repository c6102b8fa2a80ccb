# frozen_string_literal: true

module Syskit
  # The `syskit` command is syskit/cli.rb, its main commands in cli/*.rb; this file adds `syskit bus`.
  class CLI < Thor
    # `syskit bus replay|monitor`: bus traffic seen through a profile's plan,
    # from a candump log or live from a SocketCAN interface; `syskit bus
    # timing`: the worst-case timing of the traffic a profile declares.
    class Bus < Thor
      extend Help
      include Support

      def self.exit_on_failure?
        true
      end

      def self.basename
        'syskit'
      end

      check_unknown_options!

      class_option :trace, type: :boolean, default: false, hide: true, desc: 'show the backtrace of errors'
      class_option :app, type: :string, desc: 'the app directory'
      class_option :robot, type: :string, default: 'default', desc: 'the robot configuration (config/robots/NAME.rb)'
      class_option :bus, type: :string, desc: 'the bus of the plan (default: its only bus with devices)'

      desc 'replay [PROFILE] LOGFILE', 'what each device of a bus receives from a candump log'
      long_desc <<~TEXT
        Reads a candump log (candump -l or -L) and reports, per device attached
        to the bus in PROFILE's plan (without PROFILE, the app's first profile,
        as for plan): the frames it receives by its can_id filter,
        the distinct ids, the first and last time and the mean rate; then the
        frames no device receives and those several devices receive.

        A filter whose id or mask exceeds 0x7FF is extended: it only matches
        extended (8-digit) ids; other filters only match standard (3-digit) ids.

        Malformed lines are counted and reported; --strict makes them an error.

        Example: syskit bus replay Live::Base --bus can0 logs/can0.log
      TEXT
      method_option :interface, type: :string,
                                desc: 'the interface of the log to read (default: the first one in the log)'
      method_option :format, type: :string, default: 'text', enum: %w[text json], desc: 'output format'
      method_option :strict, type: :boolean, default: false, desc: 'fail on malformed lines'
      def replay(profile_name, log_path = nil)
        unless log_path
          log_path = profile_name
          profile_name = nil
        end
        require_once 'syskit/bus/replay'
        with_plan(profile_name, __method__) do |dispatcher, source, declared_bus|
          replay = ::Syskit::Bus::Replay.new(dispatcher, log_path, interface: options[:interface], source: source,
                                                                   declared_bus: declared_bus)
          print_report(replay.run(strict: options[:strict]))
        end
      end

      desc 'monitor [PROFILE]', 'watch a live SocketCAN bus through the devices of a plan'
      long_desc <<~TEXT
        Opens the SocketCAN interface IFACE (Linux, classic and CAN FD frames)
        and shows the replay table of the bus in PROFILE's plan (without
        PROFILE, the app's first profile), refreshed every --interval seconds,
        until Ctrl-C (or --duration seconds). The "Now" column is the rate
        during the last interval.

        A virtual bus to try it:
          sudo modprobe vcan; sudo ip link add dev vcan0 type vcan; sudo ip link set up vcan0

        Example: syskit bus monitor Live::Base --bus can0 --interface vcan0
      TEXT
      method_option :interface, type: :string, required: true, desc: 'the SocketCAN interface (can0, vcan0...)'
      method_option :interval, type: :numeric, default: 1.0, desc: 'seconds between two refreshes'
      method_option :duration, type: :numeric, desc: 'stop after this many seconds'
      method_option :format, type: :string, default: 'text', enum: %w[text json],
                             desc: 'json prints the final report only'
      def monitor(profile_name = nil)
        load_monitor
        with_plan(profile_name, __method__) do |dispatcher, source, declared_bus|
          io = ::Syskit::Bus::SocketCAN.open(options[:interface])
          begin
            source = source.merge('interface' => options[:interface])
            monitor = ::Syskit::Bus::Monitor.new(dispatcher, io, source: source, interval: options[:interval],
                                                                 live: options[:format] == 'text',
                                                                 declared_bus: declared_bus)
            print_report(monitor.run(duration: options[:duration]))
          ensure
            io.close
          end
        end
      rescue Interrupt
        # Ctrl-C before the bus is opened: stop quietly, as the shell expects.
        exit(130)
      end

      desc 'timing [PROFILE]', 'worst-case response time of every frame declared on a CAN bus'
      long_desc <<~TEXT
        Analyses the frames that PROFILE's robot (without PROFILE, the app's
        first profile, as for syskit plan) declares on the CAN bus --bus
        (.frame on its devices, .bitrate on the bus): for each frame, in
        priority order, its transmission time, blocking, worst-case response
        time and slack, with the revised analysis of Davis, Burns, Bril and
        Lukkien (Real-Time Systems 35, 2007); then the bus's utilisation.

        Exit status 1 when a frame can miss its deadline.

        Example: syskit bus timing Live::Base --bus can0 --format json
      TEXT
      method_option :format, type: :string, default: 'text', enum: %w[text json], desc: 'output format'
      def timing(profile_name = nil)
        require_once 'syskit/cli/bus_timing'
        with_app(robots: [options[:robot]]) do |app|
          profile = find_profile(app, profile_name, command: 'bus timing')
          # The traffic is the profile's, whatever the robot; a robot that
          # does not exist is still refused, as plan and replay refuse it.
          app.robot_config(options[:robot])
          result, bus = BusTiming.analyse(profile, options[:bus])
          puts BusTiming.render(result, bus, profile, options[:format])
          exit(1) unless result.schedulable?
        end
      end

      private

      # The monitor needs the ffi gem, which only it loads.
      def load_monitor
        require_once 'syskit/bus/monitor'
      rescue LoadError => e
        report_error(Error.new("syskit bus monitor needs the ffi gem: #{e.message}",
                               hint: 'run bundle install (or gem install ffi)'), nil)
      end

      # Loads the app, generates PROFILE's plan and yields the dispatcher of
      # --bus with what the report says about its source, and the plan's
      # entry of the bus when it declares CAN traffic.
      def with_plan(profile_name, command)
        # The bus tools are loaded by their commands only: `syskit plan`
        # does not pay for them (nor for ffi, needed by monitor alone).
        require_once 'syskit/bus/dispatcher'
        with_app(robots: [options[:robot]]) do |app|
          profile = find_profile(app, profile_name, command: "bus #{command}")
          plan = Network::Generator.plan_profile(app, profile, robot: options[:robot]).plan
          bus = options[:bus] || only_bus(plan)
          declared = plan.find_bus(bus)
          declared = nil unless declared && (declared.bitrate || declared.frames.any?)
          yield ::Syskit::Bus::Dispatcher.from_plan(plan, bus), { 'profile' => plan.profile, 'robot' => plan.robot },
                declared
        end
      end

      def print_report(report)
        if options[:format] == 'json'
          require_once 'json'
          puts ::JSON.pretty_generate(report.to_h)
        else
          require_once 'syskit/bus/report_text'
          $stdout.write(::Syskit::Bus::ReportText.render(report))
        end
      end

      def only_bus(plan)
        buses = plan.devices.filter_map(&:bus).uniq.sort
        return buses.first if buses.size == 1

        if buses.empty?
          raise UnknownName.new("the plan of #{plan.profile} has no bus with devices",
                                hint: 'attach devices to a bus with through')
        end
        raise UnknownName.new("the plan of #{plan.profile} has several buses",
                              hint: "choose one with --bus (#{buses.join(', ')})")
      end
    end

    desc 'bus SUBCOMMAND', "a bus through a plan: replay a candump log, monitor it live, its frames' timing"
    subcommand 'bus', Bus
  end
end
