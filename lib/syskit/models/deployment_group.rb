# frozen_string_literal: true

require 'syskit/models/deployment_group/lookups'

module Syskit
  module Models
    # Syskit's deployment groups: the deployed tasks a network may use,
    # declared by a robot configuration (Config::RobotConfig is one), a
    # profile or requirements:
    #
    #   use_deployment 'test_canbus'                   # a deployment of an .orogen file
    #   use_deployment OroGen.gps_ublox.Task => 'gps'  # one task, named 'gps'
    #
    # The group of requirements or of a profile deploys the tasks of
    # their network before the robot's (see Network::Deploy).
    class DeploymentGroup
      include Lookups

      # Options of use_deployment that only matter to a running system
      # (how processes are started): accepted, no effect on plans. +on:+,
      # the process server a deployment runs on, is recorded (see
      # #process_server_of).
      NO_OPTIONS = {}.freeze
      RUNTIME_OPTIONS = %i[on simulation loader process_managers read_only logger_name wait valgrind
                           valgrind_options gdb gdb_options log_level output oro_logfile working_directory
                           cmdline_args].freeze

      attr_reader :deployments

      # The group without deployments (what requirements have until a
      # statement gives them some).
      def self.empty
        @empty ||= new.freeze
      end

      # +app+ resolves deployments and task models given by name (by
      # default the loaded app, as Syskit's +DeploymentGroup.new+).
      def initialize(app = nil)
        @app = app
        @deployments = []
        @deployed_tasks = {}
        @process_server_names = {}
        @lookups = {}
      end

      # The name of the process server deployment +name+ runs on, as its
      # statement's +on:+ gave it; nil when it said none.
      def process_server_of(name)
        @process_server_names[name]
      end

      # Deploys task instances, as Syskit's use_deployment does:
      #
      #   use_deployment 'test_canbus'                    # a deployment of an .orogen file
      #   use_deployment 'test_canbus' => 'left_'         # ... its task names prefixed
      #   use_deployment 'test_canbus', prefix: 'left_'   # the same
      #   use_deployment OroGen.gps_ublox.Task => 'gps'   # one task, named gps
      #   use_deployment 'gps_ublox::Task' => 'gps'       # the same, by model name
      #
      # Where and how processes start (+on:+, +valgrind:+, ...) does not
      # change a plan: those options are accepted and ignored. As each
      # statement of a group, it returns the deployments it added.
      def use_deployment(*specs)
        location = Location.of_caller
        # The trailing `Model => 'name'` mappings and options come as one
        # Hash, taken off the list here: declared as keywords (**options,
        # prefix:), they cost two more hashes and an array per statement,
        # and a robot has one statement per device. Most statements give
        # no option: their hash is all mappings.
        options = specs.last.is_a?(Hash) ? specs.pop : NO_OPTIONS
        mappings = options
        if options.any? { |key, _| key.is_a?(Symbol) }
          mappings = options.reject { |key, _| key.is_a?(Symbol) }
          check_options(options.keys.grep(Symbol) - [:prefix], location)
        end
        prefix = options[:prefix]
        running_on(options[:on], location) do
          specs.each { |spec| add_spec(spec, prefix, location) }
          mappings.each { |spec, value| add_mapping(spec, value, prefix, location) }
        end
      end

      # Every deployment an .orogen file declares (Syskit's
      # use_deployments_from).
      def use_deployments_from(*libraries, **options)
        location = Location.of_caller
        check_options(options.keys, location)
        running_on(options[:on], location) do
          libraries.each do |name|
            library = app.using_task_library(name.to_s, location: location)
            library.deployments.each_value { |deployment| add(deployment, location) }
          end
        end
      end

      # Tasks started outside of Syskit's control, integrated in the
      # network: planned as deployed tasks of their own name.
      def use_unmanaged_task(mappings = {}, **options)
        location = Location.of_caller
        raise unmanaged_without_model(mappings, location) unless mappings.is_a?(Hash)

        mappings = mappings.merge(options.reject { |key, _| key.is_a?(Symbol) })
        check_options(options.keys.grep(Symbol), location)
        running_on(options[:on], location) { mappings.each { |model, name| add_mapping(model, name, nil, location) } }
      end

      # Ruby task contexts (see RubyTaskContext), each deployed as a task of
      # its own name: +use_ruby_tasks Generator => 'setpoint'+, on the
      # process server +on:+ when given.
      def use_ruby_tasks(mappings = {}, on: nil, **more)
        location = Location.of_caller
        running_on(on, location) do
          mappings.merge(more).each do |model, name|
            raise not_a_ruby_task(model, name, location) unless model.is_a?(Class) && model < RubyTaskContext

            add_mapping(model, name, nil, location)
          end
        end
      end

      # Adds the deployed tasks of +group+ that this one does not have (a
      # deployment of the same name, deploying the same tasks, is the same).
      def use_group(group)
        location = Location.of_caller
        group.deployments.each do |d|
          add(d, location) unless same_deployment?(d)
          server = group.process_server_of(d.name)
          @process_server_names[d.name] ||= server if server
        end
        self
      end

      def empty?
        @deployments.empty?
      end

      # Frozen with what it lists (its lookups are still computed).
      def freeze
        @deployments.freeze
        @deployed_tasks.freeze
        @process_server_names.freeze
        super
      end

      # A copy, to which statements add without changing this group.
      def initialize_copy(other)
        super
        @deployments = @deployments.dup
        @deployed_tasks = @deployed_tasks.dup
        @process_server_names = @process_server_names.dup
        @lookups = {}
      end

      # Deployed tasks by name.
      def deployed_tasks
        @deployed_tasks.values
      end

      def to_s
        "deployment group (#{@deployed_tasks.keys.join(', ')})"
      end
      alias inspect to_s

      private

      def app
        @app || Syskit.app || raise(DeploymentError.new('deployments are named in an app: no app is loaded',
                                                        location: Location.of_caller,
                                                        hint: 'give the deployment model instead of its name'))
      end

      # Runs a statement's block, recording +on+ (a process server name, or
      # nil) for the deployments it adds; returns them.
      def running_on(on, location)
        check_process_server(on, location) if on
        before = @deployments.size
        yield
        added = @deployments.drop(before)
        added.each { |d| @process_server_names[d.name] = on.to_s } if on
        added
      end

      # Groups of profiles and requirements take +on:+ as given; a robot's
      # configuration checks it names a process server it declares.
      def check_process_server(_name, _location); end

      def unmanaged_without_model(given, location)
        DeploymentError.new(
          "use_unmanaged_task takes a task model and the name of its task, got #{given.inspect} alone",
          location: location,
          hint: "write Syskit.conf.use_unmanaged_task OroGen.lib.Task => '#{given.is_a?(String) ? given : 'name'}'"
        )
      end

      def same_deployment?(deployment)
        deployment.task_activities.all? do |task|
          own = @deployed_tasks[task.name]
          own && own.model.equal?(task.model) && own.deployment.name == deployment.name
        end
      end

      def add(deployment, location)
        @deployments << deployment
        @lookups.clear
        deployment.task_activities.each do |task|
          if (other = @deployed_tasks[task.name])
            raise DeploymentError.new(
              "deployed task name '#{task.name}' is used twice (#{other} and #{task})",
              location: location, hint: 'deployed task names must be unique on a robot: rename one of them'
            )
          end

          @deployed_tasks[task.name] = task
        end
      end

      def check_options(keys, location)
        unknown = keys - RUNTIME_OPTIONS
        return if unknown.empty?

        raise DeploymentError.new(
          "use_deployment does not know the option#{'s' if unknown.size > 1} #{unknown.map { |k| "#{k}:" }.join(', ')}",
          location: location,
          hint: 'options that change the plan: prefix:; accepted and ignored: ' \
                "#{RUNTIME_OPTIONS.map { |o| "#{o}:" }.join(', ')}"
        )
      end

      def add_spec(spec, prefix, location)
        case spec
        when String, Symbol then add(prefixed(named_deployment(spec.to_s, location), prefix), location)
        when Models::Deployment, Models::ConfiguredDeployment then add(prefixed(spec.orogen_model, prefix), location)
        when Hash then spec.each { |key, value| add_mapping(key, value, prefix, location) }
        else raise usage_error(spec, location)
        end
      end

      # +Model => 'name'+, +'lib::Task' => 'name'+ or +'deployment' => 'prefix'+.
      def add_mapping(key, value, prefix, location)
        unless (value.is_a?(String) || value.is_a?(Symbol)) && !value.to_s.empty?
          raise DeploymentError.new(
            "use_deployment #{key.inspect} => #{value.inspect}: the task name must be a non-empty string",
            location: location, hint: "write use_deployment #{key.inspect} => 'task_name'"
          )
        end

        model = key.is_a?(String) ? task_model_named(key, location) : key
        name = prefix ? "#{prefix}#{value}" : -value.to_s # (the user's string, deduplicated and frozen)
        return add(task_deployment(model, name, location), location) if model

        add(prefixed(named_deployment(key, location), name), location)
      end

      # The task model called +name+ ('lib::Task'), loading its library;
      # nil when +name+ is not a task model name (but a deployment's).
      def task_model_named(name, location)
        library, = name.split('::', 2)
        return unless name.include?('::') && app.orogen.available_library_names.include?(library)

        app.using_task_library(library, location: location)
        found = app.orogen.find_task_model(name)
        return found if found

        raise DeploymentError.new("task library '#{library}' has no task model '#{name}'",
                                  location: location,
                                  hint: "its task models: #{app.orogen.library(library).tasks.keys.sort.join(', ')}")
      end

      def prefixed(deployment, prefix)
        prefix ? deployment.with_prefix(prefix.to_s) : deployment
      end

      def named_deployment(name, location)
        found = app.orogen.find_deployment(name)
        return found if found

        app.orogen.libraries_declaring_deployment(name).each do |lib|
          app.using_task_library(lib, location: location)
        end
        found = app.orogen.find_deployment(name)
        return found if found

        raise DeploymentError.new(
          "no deployment named '#{name}'#{Naming.did_you_mean(name, app.orogen.all_deployment_names)}",
          location: location,
          hint: "deployments are declared in .orogen files (deployment '#{name}' do task('name', 'lib::Task') end), " \
                "or made for one task with use_deployment OroGen.lib.Task => 'name'"
        )
      end

      def task_deployment(model, name, location)
        raise usage_error(model, location) unless model.is_a?(Class) && model <= Syskit::TaskContext && model.spec

        deployment = Orogen::DeploymentSpec.new(name.to_s, location)
        deployment.add_task(name.to_s, model, location: location)
        deployment
      end

      def not_a_ruby_task(model, name, location)
        DeploymentError.new("use_ruby_tasks expects ruby task models, got #{Arguments.shown(model)}",
                            location: location,
                            hint: 'deploy task contexts of .orogen files with ' \
                                  "use_deployment #{model.inspect} => '#{name}'")
      end

      def usage_error(spec, location)
        DeploymentError.new(
          "use_deployment does not understand #{spec.inspect}",
          location: location,
          hint: "write use_deployment 'deployment_name' or use_deployment OroGen.lib.Task => 'task_name'"
        )
      end
    end
  end
end
