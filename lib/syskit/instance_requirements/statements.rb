# frozen_string_literal: true

module Syskit
  class InstanceRequirements
    # The statements that say what is asked of requirements, as profiles,
    # compositions and tests write them (+with_conf+, +with_arguments+,
    # +use+, +prefer_deployed_tasks+, +deployed_as+...): each changes the
    # requirements and returns them, or a changed copy of frozen ones (see
    # Changes#change). Part of InstanceRequirements.
    module Statements
      # Configuration sections, replacing ['default'] as in Syskit;
      # +location+: where they are chosen, for errors about them.
      def with_conf(*names, location: Location.of_caller)
        names = names.flatten.map(&:to_s)
        if names.empty?
          raise DeclarationError.new('with_conf needs at least one section name',
                                     location: location, hint: "write with_conf('default', 'forward')")
        end

        change(conf: names, conf_location: location)
      end

      # Task arguments (see Component#argument). +conf:+ is the sections
      # argument: +with_arguments(conf: ['slow'])+ is +with_conf('slow')+,
      # as in Syskit.
      def with_arguments(**arguments)
        return change(arguments: self.arguments.merge(arguments).freeze) unless arguments.key?(:conf)

        others = arguments.except(:conf)
        with_conf(*Array(arguments[:conf]), location: Location.of_caller).with_arguments(**others)
      end

      # Deployed tasks to prefer (names, regexps, or objects matching names
      # with ===, see Arguments.deployment_hint?).
      def prefer_deployed_tasks(*hints)
        hints = hints.flatten
        bad = hints.reject { |h| Arguments.deployment_hint?(h) }
        unless bad.empty?
          raise DeclarationError.new("prefer_deployed_tasks expects regexps or names, got #{bad.first.inspect}",
                                     location: Location.of_caller, hint: 'write prefer_deployed_tasks(/forward/)')
        end

        change(deployment_hints: deployment_hints | hints, declared_at: Location.of_caller)
      end

      # A deployment of its own (see Robot::MasterDevice#deployed_as).
      def deployed_as(name, on: nil) # rubocop:disable Lint/UnusedMethodArgument -- Syskit's signature
        declare_deployment(name, false, Location.of_caller)
      end

      def deployed_as_unmanaged(name, on: nil) # rubocop:disable Lint/UnusedMethodArgument -- Syskit's signature
        declare_deployment(name, true, Location.of_caller)
      end

      # Dependency injection (see DependencyInjection). The children it
      # names must be children of the composition.
      def use(*mappings)
        location = Location.of_caller
        unless composition?
          raise DeclarationError.new("use selects children of compositions, and #{self} is not one",
                                     location: location, hint: 'call use on a composition model or its requirements')
        end

        injection = selections.dup.add(*mappings).freeze
        names = injection.explicit.keys.grep(String) - selections.explicit.keys
        component_model.check_child_keys(names, location)
        component_model.check_child_selections(injection.explicit.slice(*names), location)
        change(selections: injection, declared_at: declared_at || location)
      end

      # Syskit's +add_models+: these requirements also requiring +added+
      # (a model that refines one of the models replaces it).
      def add_models(added, location: Location.of_caller)
        copy(models: Models.merge_models(models, added, location, self))
      end

      # Syskit's +with_dynamic_service+: the task model specialized with
      # the instance +as+ of its dynamic service +dynamic_name+ (see
      # Models::DynamicServices#require_dynamic_service).
      def with_dynamic_service(dynamic_name, as:, **options)
        model = component_model
        unless model.respond_to?(:require_dynamic_service)
          raise DeclarationError.new("with_dynamic_service needs a task model, #{self} has none",
                                     location: Location.of_caller, hint: 'call it on a task model')
        end

        specialized = model.specialize
        specialized.require_dynamic_service(dynamic_name, as: as, **options)
        change(models: models.map { |m| m.equal?(model) ? specialized : m })
      end

      # The transformer's frame names (+use_frames('world' => 'map')+) and
      # its block (+transformer { frames ... }+): not modelled by this gem,
      # one located warning each; the requirements stay as they are.
      def use_frames(*_mappings)
        Syskit.app&.not_modelled("use_frames on #{self} (the transformer)", Location.of_caller)
        self
      end

      def transformer(*_args)
        Syskit.app&.not_modelled("transformer on #{self}", Location.of_caller)
        self
      end

      # Deployments for the network of these requirements (Syskit's
      # deployment group): its tasks are deployed from them before the
      # robot's, as with the same statements in config/robots (see
      # Models::DeploymentGroup).
      #
      #   OroGen.rig.Tracker.use_deployment(OroGen.rig.Tracker => 'rear_tracker')
      %i[use_deployment use_unmanaged_task use_ruby_tasks use_deployments_from].each do |statement|
        define_method(statement) do |*args, **options|
          group = deployment_group.dup
          group.public_send(statement, *args, **options)
          change(deployment_group: group)
        end
      end

      # Says that the port +port_name+ gets +sample_count+ samples every
      # +period+ seconds (Syskit's +add_port_period+; see
      # #find_port_dynamics).
      def add_port_period(port_name, period, sample_count = 1)
        port_name = port_name.to_s
        dynamics = port_dynamics[port_name]&.dup || NetworkGeneration::PortDynamics.new(port_name)
        dynamics.add_trigger('period', period, sample_count)
        change(port_dynamics: port_dynamics.merge(port_name => dynamics.freeze))
      end

      # Syskit's +use_configured_deployment+: one configured deployment
      # (Models::ConfiguredDeployment) for the network of these requirements.
      def use_configured_deployment(configured)
        use_deployment(configured)
      end

      # Adds the deployed tasks of +group+ (a Models::DeploymentGroup).
      def use_deployment_group(group)
        change(deployment_group: deployment_group.dup.use_group(group))
      end

      # The same requirements, marked abstract: what fills them must still
      # be chosen (Syskit's +abstract+).
      def abstract
        change(abstract: true)
      end

      # Without the arguments given so far.
      def with_no_arguments
        change(arguments: NO_ARGUMENTS)
      end

      # Syskit's former name of with_conf.
      def use_conf(*names)
        with_conf(*names, location: Location.of_caller)
      end

      # These requirements with +srv+, a service of their component model
      # (of the placeholder standing for their models when they have none),
      # selected (as +x_srv+ does).
      def select_service(srv)
        if srv.is_a?(InstanceRequirements)
          # Requirements on a service: their arguments come along, as in Syskit.
          arguments = srv.arguments
          srv = srv.service
        end
        model = component_model || proxy_model
        unless srv.is_a?(Models::BoundDataService) && model.is_a?(Class) && model <= srv.task_model
          shown = srv.respond_to?(:task_model) ? srv : Arguments.shown(srv)
          raise DeclarationError.new("#{shown} is not a service of #{self}",
                                     location: Location.of_caller, hint: 'select one of its x_srv')
        end

        return change(service: srv) if arguments.nil? || arguments.empty?

        change(service: srv, arguments: self.arguments.merge(arguments))
      end

      # These requirements without a selected service.
      def unselect_service
        change(service: nil)
      end

      # Names the requirements (Syskit's +name=+).
      def name=(name)
        @name = name
      end

      # Which specializations to prefer when several apply.
      def prefer_specializations(hints)
        change(specialization_hints: specialization_hints + [hints])
      end

      # These requirements as the definition +name+ of +profile+.
      def named(name, profile, location, doc: nil)
        copy(class: Actions::Profile::Definition, name: name, profile: profile, declared_at: location, doc: doc).freeze
      end

      private

      def declare_deployment(name, unmanaged, location)
        change(deployment: Robot::MasterDevice::DeclaredDeployment.declare(
          name, unmanaged, location, owner: self, hint: "write deployed_as('name_of_the_task')"
        ))
      end
    end
  end
end
