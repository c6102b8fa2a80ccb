# frozen_string_literal: true

require 'syskit/network/composition_instantiation'

module Syskit
  module Network
    # Step 1: turns the requirements (device actions, definitions, models)
    # into tasks. A device gives its driver task (one per device, however
    # many compositions use it); a task model a task; a composition a
    # Composition whose children are instantiated in turn, each selected
    # through dependency injection (see Selection), the composition
    # specialized on what was selected. Equal tasks made for different
    # children are merged by the next step (Merge).
    #
    # With +stub_abstract+ (tests), what is still abstract is filled with
    # a stub: a task model providing the services, or a device and its
    # driver for a device model.
    class Instantiate
      include CompositionInstantiation

      # A task's identity for merging: model, arguments, sections,
      # deployment hints and deployment.
      def self.merge_key(model, requirements, arguments)
        [model, arguments, requirements.conf, requirements.deployment_hints, requirements.declared_deployment&.name]
      end

      # Gives +task+ the sections of +requirements+ (its +conf+ argument),
      # when they choose some: a task made with the default sections keeps
      # them as its default argument, not set, as in Syskit.
      def self.assign_conf(task, requirements)
        task.conf = requirements.conf if requirements.conf_given? || requirements.conf != task.conf
      end

      # Syskit's model-level +instanciate+: the task of +requirements+ (and
      # of its children), selected in +injection+ (a
      # DependencyInjectionContext) and added to +plan+ (any object with
      # #add, such as the plan of Syskit's tests). What is still abstract
      # becomes a task of its placeholder model, as in Syskit; nothing is
      # merged or deployed.
      def self.into_plan(plan, requirements, injection)
        network = Context.new(app: Syskit.app, requirements: [requirements])
        new(network, base: injection, placeholders: true).run
        network.raise_errors
        (network.tasks + network.compositions).each { |task| plan.add(task) }
        network.roots.first
      end

      # +base+: the selections every root is instantiated in (the
      # profile's by default); +placeholders+: abstract children become
      # placeholder tasks instead of errors.
      def initialize(context, stub_abstract: false, base: nil, placeholders: false)
        @context = context
        @drivers = Drivers.new(context)
        @stub_abstract = stub_abstract
        @placeholders = placeholders
        @building = []
        # The requirements of the root tasks, to make each root once: a
        # hash, since a profile of 10,000 devices has 10,000 roots.
        @root_requirements = {}.compare_by_identity
        profile = context.profile
        @base = base || (profile ? profile.dependency_injection_context : DependencyInjectionContext::EMPTY)
      end

      def run
        @context.requirements.each do |requirement|
          instantiate_root(requirement)
        rescue Syskit::Error => e
          @context.error(e)
        end
      end

      private

      # A profile's definition deployed on its own (+syskit_stub_and_deploy
      # (Base.nav_def)+ in a test) is instantiated in its profile's
      # selections (robot devices by device model, use, used profiles'),
      # as when the profile is generated.
      def base_of(requirement)
        own = requirement.profile
        return @base if @context.profile || !own.respond_to?(:dependency_injection_context)

        own.dependency_injection_context
      end

      def instantiate_root(requirement)
        requirement = InstanceRequirements.from(requirement) if requirement.is_a?(Robot::MasterDeviceInstance)
        unless requirement.is_a?(InstanceRequirements)
          raise NetworkError.new("#{Arguments.shown(requirement)} is not something a network can contain",
                                 location: Location.of_caller,
                                 hint: "pass a profile's action (Base.gps_dev, Base.x_def) or a model")
        end

        @root = requirement
        return if @root_requirements.key?(requirement)

        context = base_of(requirement).with(requirement.selections)
        # A device's task is the device's: only other roots need a path.
        task = instantiate(requirement, context, requirement.device ? nil : root_name(requirement), nil)
        @context.roots << task
        @root_requirements[task.requirements] = true
      ensure
        @root = nil
      end

      def root_name(requirement)
        name = requirement.name || requirement.device&.name || Naming.underscore(requirement.to_s.split('::').last)
        name.delete_suffix('_def').tr('^a-zA-Z0-9_.', '_')
      end

      # The task for +requirements+ at +path+ in the plan, +parent+ being
      # the composition it is a child of (nil for a root).
      def instantiate(requirements, context, path, parent)
        return device_task(requirements, requirements.device) if requirements.device
        return requirements.instance if requirements.instance

        model = requirements.component_model
        composition = model && model <= Composition
        if composition && (@placeholders || !requirements.abstract?)
          instantiate_composition(model, requirements, context, path, parent)
        elsif requirements.abstract?
          abstract_task(requirements, path, parent, composition)
        else
          component_task(model, requirements, context, path, parent)
        end
      end

      # What stands for abstract +requirements+: a stub or a placeholder
      # task when asked for (a composition is never stubbed), else an error.
      def abstract_task(requirements, path, parent, composition)
        return stub_task(requirements, path, parent) if @stub_abstract && !composition
        return placeholder_task(requirements, path, parent) if @placeholders

        raise abstract(requirements, path, parent)
      end

      # A task context: the driver of a device when the model drives one
      # and injection selects it, else a task of its own (merged with an
      # equal one).
      def component_task(model, requirements, context, path, parent)
        device = selected_device(model, context)
        return device_task(requirements, device, model: model) if device

        # Syskit's instanciate leaves a driver without its device (to be
        # given, or stubbed): only a network refuses it.
        unless model.driver_services.empty? || @placeholders
          return stub_driver(model, requirements) if @stub_abstract

          raise no_device(model, requirements, path, parent)
        end

        task = model.new(task_arguments(requirements, parent))
        Instantiate.assign_conf(task, requirements)
        task.plan_path = path
        task.root_location = @root&.declared_at
        @context.add_task(task, nil, requirements)
      end

      # The device injection selects for the driver services of +model+.
      def selected_device(model, context)
        model.driver_services.each do |srv|
          value = context.direct_selection_for(srv.driven_device_model)
          device = InstanceRequirements.from(value).device if value
          return device if device
        end
        nil
      end

      # The driver task of +device+ (made once), with what +requirements+
      # asks of it.
      def device_task(requirements, device, model: nil)
        existing = @context.task_for(device)
        if existing
          check_same_use(existing, requirements, device)
          return existing
        end

        requirement = requirements
        requirement = requirements.merge_selection(InstanceRequirements.from(device)) unless requirements.device
        @drivers.instantiate_device(requirement, expected_model: model)
      end

      # A device's task serves one set of sections and arguments.
      def check_same_use(task, requirements, device)
        conf = requirements.conf
        return if conf == task.conf && requirements.arguments.all? { |k, v| task.arguments[k] == v }

        first = task.requirements
        raise NetworkError.new(
          "#{device} is used with #{describe_use(first)} (#{first.declared_at}) and with " \
          "#{describe_use(requirements)}, but its driver is one task",
          location: requirements.declared_at || device.declared_at,
          hint: 'use the device the same way in both places, or declare two devices'
        )
      end

      # The sections and the arguments given (not those binding the device).
      def describe_use(requirements)
        parts = ["sections #{requirements.conf.join(', ')}"]
        given = requirements.arguments.reject { |_, value| value.equal?(requirements.device) }
        parts << "arguments #{given}" unless given.empty?
        parts.join(' and ')
      end

      def task_arguments(requirements, parent)
        arguments = {}
        requirements.arguments.each do |key, value|
          value = resolve_argument(value, parent)
          arguments[key] = value unless value.equal?(Compat::DelayedArgument::UNSET)
        end
        arguments.freeze
      end

      # A delayed argument (+from(:parent_task).speed+) takes the parent's.
      def resolve_argument(value, parent)
        return value unless value.is_a?(Compat::DelayedArgument)

        value.resolve(parent)
      end

      def placeholder_task(requirements, path, parent)
        model = Models::Placeholder.for(requirements.models)
        task = model.new(task_arguments(requirements, parent))
        Instantiate.assign_conf(task, requirements)
        task.plan_path = path
        @context.add_task(task, nil, requirements)
      end

      def stub_task(requirements, path, parent)
        model = requirements.models.find { |m| m.is_a?(Models::DeviceModel) }
        return stub_device_task(model, requirements, path) if model

        # A tag's placeholder stands for its services.
        services = requirements.models.flat_map { |m| m.is_a?(Models::Placeholder) ? m.proxied_data_service_models : m }
        stub = Test::StubModels.service_provider(services)
        component_task(stub, requirements.merge_selection(InstanceRequirements.new([stub])), @base, path, parent)
      end

      def stub_device_task(model, requirements, path)
        robot = (@stub_robot ||= Robot::Definition.new(nil))
        driver = Test::StubModels.device_driver(model)
        device = robot.add_device(Robot::MasterDeviceInstance, model, path.tr('.', '_'),
                                  using: driver, options: {}, location: requirements.declared_at)
        device.driver_model = driver
        device_task(requirements, device)
      end

      def stub_driver(model, requirements)
        srv = model.driver_services.first
        robot = (@stub_robot ||= Robot::Definition.new(nil))
        device = robot.add_device(Robot::MasterDeviceInstance, srv.driven_device_model,
                                  "#{srv.name}_stub#{robot.each_master_device.count}",
                                  using: model, options: {}, location: requirements.declared_at)
        device.driver_model = srv
        device_task(requirements, device, model: model)
      end

      def abstract(requirements, path, parent, model = nil)
        InstantiationErrors.abstract_child(requirements, path, parent, error_location(requirements), model)
      end

      def no_device(model, requirements, path, parent)
        InstantiationErrors.no_device(model, path, parent, error_location(requirements))
      end

      # Errors point at the root requirement's declaration (the definition,
      # where a +use+ fixes them), else at the child's; a tag of a profile
      # this one uses, at the use_profile statement that selects for it.
      def error_location(requirements)
        tag_profile = requirements.profile if requirements.name&.end_with?('_tag')
        planned = @context.profile
        used_at = planned.use_profile_location(tag_profile) if tag_profile && planned && !planned.equal?(tag_profile)
        used_at || @root&.declared_at || requirements.declared_at
      end
    end
  end
end
