# frozen_string_literal: true

module Syskit
  # Test support (see syskit/test and syskit/test/self).
  module Test
    # Devices, buses and drivers made up for a test, on a throw-away robot,
    # and their configuration through the network generator with stub
    # deployments (one deployed task per task, named after its device).
    module Stubs
      # A device of +model+; its driver is +driver+ (or +using:+, as
      # Syskit's tests write it), the described task model when it drives
      # +model+, else a stub driver. The device's own settings are given as
      # in Syskit: +doc:+, +period:+, +burst:+, +sample_size:+.
      def syskit_stub_device(model, as: nil, driver: nil, using: nil, **settings)
        location = Location.of_caller
        driver ||= using || described_driver_for(model) || StubModels.device_driver(model)
        device = syskit_stub_robot.add_device(Robot::MasterDeviceInstance, model, as || syskit_stub_name('dev'),
                                              using: driver, options: {}, location: location)
        device.driver_model = driver
        apply_stub_settings(device, settings, location)
      end

      # A bus of +model+; its driver is +driver+, the described task model
      # when it drives the bus, else a stub demultiplexing driver.
      def syskit_stub_com_bus(model, as: nil, driver: nil)
        unless model.is_a?(Models::ComBusModel)
          raise DeclarationError.new("syskit_stub_com_bus expects a bus model, got #{model.inspect}",
                                     location: Location.of_caller)
        end

        driver ||= described_driver_for(model) || StubModels.bus_driver(model)
        bus = syskit_stub_robot.add_device(Robot::ComBus, model, as || syskit_stub_name('bus'),
                                           using: driver, options: {}, location: Location.of_caller)
        bus.driver_model = driver
        bus
      end

      # A device attached to +bus+ (a stubbed bus, or a bus model to stub).
      # Its model is the one the described task drives, else a new model of
      # +base_model:+'s class (the seed also calls it +parent_model:+).
      def syskit_stub_attached_device(bus, as: nil, client_to_bus: true, bus_to_client: true,
                                      base_model: nil, parent_model: nil, driver: nil)
        bus = syskit_stub_com_bus(bus) if bus.is_a?(Models::ComBusModel)
        base = base_model || parent_model || Syskit::Device
        model, driver = attached_model_and_driver(bus, base, driver, bus_to_client, client_to_bus)
        # A bus attached to a bus (+base_model: N2k::Bus+) is a bus itself.
        kind = model.is_a?(Models::ComBusModel) ? Robot::ComBus : Robot::MasterDeviceInstance
        device = syskit_stub_robot.add_device(kind, model, as || syskit_stub_name('dev'),
                                              using: driver, options: {}, location: Location.of_caller)
        device.driver_model = driver
        syskit_stub_robot.attach(device, bus, client_to_bus: client_to_bus, bus_to_client: bus_to_client,
                                              location: Location.of_caller)
        device
      end

      # Generates the network of +device+ (and its buses) with stub
      # deployments, configures it in order, and returns the device's task.
      # The task is also available as +task+ afterwards.
      #
      # Given a task model (or its requirements), its devices are stubbed
      # first (see TaskAssertions#is_configurable); given a composition (or
      # its requirements), the composition task, as syskit_stub_and_deploy.
      def syskit_stub_deploy_and_configure(device)
        device = device.to_instance_requirements if device.is_a?(Class) && device < Component
        if device.is_a?(InstanceRequirements) && !device.device
          return syskit_stub_requirements_and_configure(device) unless device.composition?

          return syskit_stub_and_deploy(device)
        end

        requirement = device.is_a?(Robot::MasterDeviceInstance) ? InstanceRequirements.from(device) : device
        result = syskit_stub_generate([requirement])
        @task = result.task_for(requirement.device)
      end

      # Generates the network of +model+ (a composition or task model,
      # requirements such as +Cmp.use(...)+, or the name of a task model
      # its block declares) as Syskit's tests do: what is
      # still abstract is stubbed (a task providing the services, a device
      # and its driver), every task stub-deployed and configured. Returns
      # the root task (the composition), also available as +task+.
      # Syskit's +recursive:+ and +as_missions:+ are accepted: what nothing
      # selects is always stubbed, at any depth, and there is no Roby plan
      # whose missions they would be. So is +remote_task:+ (whether the
      # stub deployments would run in a process of their own): nothing runs.
      def syskit_stub_and_deploy(model = syskit_described_model, recursive: true, as_missions: false, # rubocop:disable Lint/UnusedMethodArgument
                                 remote_task: false, &block) # rubocop:disable Lint/UnusedMethodArgument
        # A name and a block: a task model of that name, the block its body.
        if model.respond_to?(:to_str)
          model = TaskContext.new_submodel(name: model.to_str, &block)
          block = nil
        end
        models = model.is_a?(Array) ? model : [model]
        requirements = models.map { |m| Test.requirements_of(m) }
        result = syskit_stub_generate(requirements, &block)
        roots = result.context.roots
        @task = model.is_a?(Array) ? roots : roots.first
      end
      alias syskit_stub_network syskit_stub_and_deploy

      # Generates +requirements+ with stub deployments and stubbed
      # abstract children.
      def syskit_stub_generate(requirements)
        result = Network::Generator.new(Test.app, requirements, stub_deployments: true, stub_abstract: true).generate
        @syskit_stub_result = result
      end

      # The plan generated by the last syskit_stub_deploy_and_configure.
      def syskit_stub_plan
        @syskit_stub_result&.plan
      end

      # Merges +data+ into the configuration sections +conf+ of +task_model+
      # (made when missing) for this test, as Syskit's syskit_stub_conf:
      # +syskit_stub_conf(OroGen.lib.Task, 'default', data: { 'gain' => 2 })+.
      def syskit_stub_conf(task_model, *conf, data: {})
        app = Syskit.app || flunk('syskit_stub_conf needs a loaded app')
        @syskit_stubbed_conf = true
        app.stub_conf(task_model, conf, data, Location.of_caller)
      end

      def after_teardown
        Syskit.app&.clear_conf_stubs if @syskit_stubbed_conf
        super
      end

      # What syskit_stub_device sets on the device, as Syskit's does.
      STUB_SETTINGS = %i[doc period burst sample_size].freeze

      private

      # The described model (+describe Compositions::X do+).
      def syskit_described_model
        desc = self.class.respond_to?(:desc) ? self.class.desc : nil
        return desc if desc.is_a?(Class) && desc < Component

        flunk "syskit_stub_and_deploy needs a model, or `describe Model do ... end`, not #{desc.inspect}"
      end

      def apply_stub_settings(device, settings, location)
        unknown = settings.keys - STUB_SETTINGS
        unless unknown.empty?
          raise DeclarationError.new(
            "syskit_stub_device: unknown option(s) #{unknown.map { |k| "#{k}:" }.join(', ')}" \
            "#{Naming.did_you_mean(unknown.first, %i[as driver using] + STUB_SETTINGS)}",
            location: location, hint: "it takes as:, driver: (or using:) and the device's #{STUB_SETTINGS.join(':, ')}:"
          )
        end
        settings.each { |name, value| device.public_send(name, value) }
        device
      end

      def syskit_stub_robot
        @syskit_stub_robot ||= Robot::Definition.new(nil)
      end

      def syskit_stub_name(prefix)
        @syskit_stub_counters ||= Hash.new(0)
        index = @syskit_stub_counters[prefix]
        @syskit_stub_counters[prefix] += 1
        "#{prefix}#{index}"
      end

      # The described task model, when the test is in `describe TaskModel`
      # and it drives +model+.
      def described_driver_for(model)
        desc = self.class.respond_to?(:desc) ? self.class.desc : nil
        return unless desc.is_a?(Class) && desc < TaskContext

        desc unless desc.driver_services_for(model).empty?
      end

      def attached_model_and_driver(bus, base, driver, bus_to_client, client_to_bus)
        return [driver_model_for(driver, base), driver] if driver

        desc = described_task_model
        driven = desc&.driven_device_models&.find { |m| !m.is_a?(Models::ComBusModel) && m.fullfills?(base) }
        return [driven, desc] if driven

        model = StubModels.device_model(base)
        directions = { bus_to_client: bus_to_client, client_to_bus: client_to_bus }
        # The described task talks to the bus but drives no device yet (no
        # driver_for): it drives the stub device, so that the test checks it
        # rather than a stub driver.
        if desc&.driven_device_models&.empty? && StubModels.bus_client?(desc, bus.model, **directions)
          return [model, StubModels.described_driver(desc, model)]
        end

        [model, StubModels.client_driver(model, bus.model, **directions)]
      end

      # The task model of the enclosing +describe+, if it describes one.
      def described_task_model
        desc = self.class.respond_to?(:desc) ? self.class.desc : nil
        desc if desc.is_a?(Class) && desc < TaskContext
      end

      def driver_model_for(driver, base)
        driver.driven_device_models.find { |m| m.fullfills?(base) } ||
          raise(DeclarationError.new("#{driver.name} drives no device providing #{base}",
                                     location: Location.of_caller))
      end
    end

    StubModels = Network::StubModels

    # The requirements +object+ stands for: itself, what its action stands
    # for (+to_action+), or a model's (+to_instance_requirements+).
    # What Roby's planners return (an action of an action interface, not
    # modelled) needs the runtime: the test skips.
    def self.requirements_of(object)
      object = object.to_action if !object.respond_to?(:to_instance_requirements) && object.respond_to?(:to_action)
      not_modelled = object.is_a?(Module) && object.singleton_class.include?(Compat::NotModelledModel)
      if not_modelled || object.is_a?(Compat::NotModelledValue)
        raise Minitest::Skip, "#{object} (a Roby planner's result) #{RuntimeOnly::REASON}"
      end

      object.respond_to?(:to_instance_requirements) ? object.to_instance_requirements : object
    end
  end
end
