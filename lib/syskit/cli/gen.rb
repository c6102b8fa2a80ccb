# frozen_string_literal: true

module Syskit
  # The `syskit` command line (see syskit/cli.rb), here given its `gen` subcommand.
  class CLI < Thor
    # `syskit gen app|dev|bus|orogen|profile`: files that follow the app's
    # conventions, each model with its test. Nothing is ever overwritten
    # without --force, and a refused command writes nothing.
    class Gen < Thor
      extend Help
      include Support

      # Loaded when a generator runs (see Help#libraries).
      GENERATORS = %w[app device bus orogen profile service composition orogen_conf task_library]
                   .map { |name| "syskit/generators/#{name}_generator" }.freeze

      def self.libraries(_command_name)
        ['syskit', *GENERATORS]
      end

      EXAMPLES = <<~TEXT
        Examples:
          syskit gen app awesome_robot           # a new app in ./awesome_robot
          syskit gen dev gps/ublox/f9            # Devices::GPS::Ublox::F9
          syskit gen bus can                     # Devices::Bus::CAN
          syskit gen srv pose                    # Services::Pose
          syskit gen cmp arm_control             # Compositions::ArmControl
          syskit gen tasklib gps_ublox::F9Task   # a new gps_ublox.orogen
          syskit gen orogen gps_ublox            # the extension of gps_ublox.orogen
          syskit gen orogenconf gps_ublox::Task  # config/orogen/gps_ublox::Task.yml
          syskit gen profile live/base           # Profiles::Live::Base

        Names are given in path form (gps/ublox/f9) or constant form
        (GPS::Ublox::F9); the acronyms of config/syskit.yml are kept (GPS, not
        Gps). Each model is in the file its name says, with a test next to it
        (models/devices/gps/ublox/f9.rb, test/devices/gps/ublox/test_f9.rb).
      TEXT

      def self.exit_on_failure?
        true
      end

      def self.basename
        'syskit'
      end

      check_unknown_options!

      # `syskit gen --help`: the commands, then examples of each.
      def self.help(shell, subcommand = false) # rubocop:disable Style/OptionalBooleanParameter -- Thor's signature
        super
        shell.say
        shell.say EXAMPLES
      end

      # No default: the main command parses --trace first, and a default here
      # would override what it found.
      class_option :trace, type: :boolean, hide: true, desc: 'show the backtrace of errors'
      class_option :force, type: :boolean, default: false, desc: 'overwrite files that exist'
      class_option :dry_run, type: :boolean, default: false, desc: 'list the files that would be written, write nothing'

      desc 'app NAME', 'create a new app in the directory NAME'
      long_desc <<~TEXT
        Creates the directory NAME (a relative or absolute path) with an app's
        layout: models/{devices,services,orogen,profiles,typekits}, config/orogen,
        config/robots/default.rb, config/syskit.yml, test/, a Rakefile, a
        Gemfile naming this syskit (its version, or this checkout's path), a
        .gitignore, a README and a first profile, Profiles::Base, with its
        test. The app's name is NAME's basename, camelized, dashes read as
        underscores (awesome_robot, awesome-robot -> AwesomeRobot). `rake test`
        and `bundle exec rake test` pass in the new app.

        Example: syskit gen app awesome_robot
      TEXT
      def app(name)
        generate { |opts| Generators::AppGenerator.new(name, **opts) }
      end

      desc 'dev TYPE/MANUFACTURER/MODEL', 'create a device model and its test'
      long_desc <<~TEXT
        Creates models/devices/TYPE/MANUFACTURER/MODEL.rb, defining
        AppName::Devices::Type::Manufacturer::Model with device_type, and its
        test in test/devices/TYPE/MANUFACTURER/test_MODEL.rb.

        Example: syskit gen dev gps/ublox/f9 (or GPS::Ublox::F9)
      TEXT
      method_option :app, type: :string, desc: 'the app directory (default: the app containing the current directory)'
      def dev(name)
        generate { |opts| Generators::DeviceGenerator.new(target_app, name, **opts) }
      end

      desc 'bus NAME', 'create a communication bus model and its test'
      long_desc <<~TEXT
        Creates models/devices/bus/NAME.rb, defining AppName::Devices::Bus::NAME
        with com_bus_type (message type /canbus/Message, to adapt) and an
        attribute of the devices attached to it, and its test in
        test/devices/bus/test_NAME.rb. NAME may be given with its namespace
        (bus/can) or without (can).

        Example: syskit gen bus can
      TEXT
      method_option :app, type: :string, desc: 'the app directory (default: the app containing the current directory)'
      def bus(name)
        generate { |opts| Generators::BusGenerator.new(target_app, name, **opts) }
      end

      desc 'srv NAME', 'create a data service and its test'
      long_desc <<~TEXT
        Creates models/services/NAME.rb, defining AppName::Services::NAME with
        data_service_type, and its test in test/services/test_NAME.rb. Device
        models and drivers provide data services; other components connect to
        their ports. NAME may have a namespace (sensing/pose).

        Example: syskit gen srv pose
      TEXT
      method_option :app, type: :string, desc: 'the app directory (default: the app containing the current directory)'
      def srv(name)
        generate { |opts| Generators::ServiceGenerator.new(target_app, name, **opts) }
      end

      desc 'cmp NAME', 'create a composition and its test'
      long_desc <<~TEXT
        Creates models/compositions/NAME.rb, defining AppName::Compositions::NAME
        (a Syskit::Composition: children, connections, exports), and its test
        in test/compositions/test_NAME.rb. Profiles define what the robot runs
        with compositions: define 'x', Compositions::NAME.use('child' => x_dev).
        NAME may have a namespace (control/arm).

        Example: syskit gen cmp arm_control
      TEXT
      method_option :app, type: :string, desc: 'the app directory (default: the app containing the current directory)'
      def cmp(name)
        generate { |opts| Generators::CompositionGenerator.new(target_app, name, **opts) }
      end

      desc 'orogen LIB', 'create the Syskit extension file of a task library and its test'
      long_desc <<~TEXT
        Creates models/orogen/LIB.rb with one Syskit.extend_model block per
        task context of LIB.orogen, where driver_for, provides, configure and
        stub go, and its test in test/orogen/test_LIB.rb. LIB.orogen is
        looked for as using_task_library does: in the app's models/orogen/,
        SYSKIT_OROGEN_PATH, then the libraries bundled with syskit.

        Example: syskit gen orogen gps_ublox
      TEXT
      method_option :app, type: :string, desc: 'the app directory (default: the app containing the current directory)'
      def orogen(library)
        generate { |opts| Generators::OrogenGenerator.new(target_app, library, **opts) }
      end

      desc 'tasklib LIB[::TASK]', 'create a new task library (LIB.orogen, one task context), its extension and test'
      long_desc <<~TEXT
        Creates models/orogen/LIB.orogen, a task library in oroGen's syntax
        with one task context, TASK (Task by default), that declares a
        property and an output port, and examples in comments of what
        else a task context declares. Also writes its extension,
        models/orogen/LIB.rb, and test/orogen/test_LIB.rb, as gen orogen
        does. A library of that name bundled with syskit, in a bundle or on
        SYSKIT_OROGEN_PATH is not hidden: extend it with gen orogen LIB.

        Example: syskit gen tasklib gps_ublox::F9Task
      TEXT
      method_option :app, type: :string, desc: 'the app directory (default: the app containing the current directory)'
      def tasklib(name)
        generate { |opts| Generators::TaskLibraryGenerator.new(target_app, name, **opts) }
      end

      desc 'orogenconf LIB::TASK', 'create the configuration file of a task model, with its properties'
      long_desc <<~TEXT
        Creates config/orogen/LIB::TASK.yml with a 'default' section that sets
        every property of the task to its initial value (the default of its
        .orogen declaration, else its type's zero), each under its
        documentation. Edit the values, delete what you keep as is, and add
        sections for other configurations (--- name:other).

        Example: syskit gen orogenconf gps_ublox::Task
      TEXT
      method_option :app, type: :string, desc: 'the app directory (default: the app containing the current directory)'
      def orogenconf(task_name)
        generate { |opts| Generators::OrogenConfGenerator.new(target_app, task_name, **opts) }
      end

      desc 'profile PATH/NAME', 'create a profile with an empty robot block and its test'
      long_desc <<~TEXT
        Creates models/profiles/PATH/NAME.rb, defining AppName::Profiles::Path::Name
        with profile 'Name' do robot do ... end end, and its test in
        test/profiles/PATH/test_NAME.rb (is_self_contained, can_instanciate,
        can_deploy, can_configure).

        Example: syskit gen profile live/base
      TEXT
      method_option :app, type: :string, desc: 'the app directory (default: the app containing the current directory)'
      def profile(name)
        generate { |opts| Generators::ProfileGenerator.new(target_app, name, **opts) }
      end

      private

      # Runs the generator the block makes and lists what it wrote; errors
      # print as in the rest of the CLI (file:line: message, then the hint).
      def generate
        generator = nil
        reporting_errors(-> { generator&.root || @target_app }) do
          generator = yield(force: options[:force], dry_run: options[:dry_run])
          print_entries(generator, generator.run)
        end
      end

      def print_entries(generator, entries)
        prefix = options[:dry_run] ? 'would ' : ''
        entries.each { |e| puts "#{prefix}#{e.overwrite ? 'overwrite' : 'create'} #{e.path}" }
        generator.notes.each { |note| puts "note: #{note}" }
        if options[:dry_run]
          puts 'dry run: nothing was written'
        elsif generator.is_a?(Generators::AppGenerator)
          puts "#{generator.app_name} is in #{generator.dir}/; next: #{generator.next_step}"
        end
      end

      # Generators work in an app (--app or the current directory's): no
      # falling back to the example app.
      def target_app
        @target_app = Generators::Base.find_app(options[:app])
      end
    end

    desc 'gen SUBCOMMAND', 'write new files: an app, models, task libraries, configuration (with tests)'
    subcommand 'gen', Gen
  end
end
