# frozen_string_literal: true

module Syskit
  module Robot
    # What a device declared in a robot block has besides its settings
    # (Syskit's MasterDeviceInstance): its slave devices, a deployment of
    # its own, and the lookups driver code calls.
    module MasterDevice
      # A deployment declared on the device: its driver runs as the task
      # +name+ of a deployment of the same name, with no line in the robot
      # configuration; an unmanaged one is started outside of Syskit.
      DeclaredDeployment = Struct.new(:name, :unmanaged, :location) do
        # The deployment +deployed_as(name)+ declares for +owner+ (a device,
        # a requirement). A task name is any text on one line, as Orocos
        # takes it (Rock's tests write "#{Process.pid}-#{name}").
        def self.declare(name, unmanaged, location, owner:, hint:)
          unless name.respond_to?(:to_str) && name.to_str.match?(/\A[^\x00-\x1f\x7f]+\z/) && !name.to_str.strip.empty?
            raise DeclarationError.new("invalid deployed task name #{name.inspect} for #{owner}",
                                       location: location, hint: hint)
          end

          new(name.to_str, unmanaged, location)
        end
      end

      NO_SLAVES = {}.freeze
      private_constant :NO_SLAVES

      # Deploys the device's driver as the task (and deployment) +name+.
      # +on:+ (the host) has no effect on plans.
      def deployed_as(name, on: nil) # rubocop:disable Lint/UnusedMethodArgument
        declare_deployment(name, false, Location.of_caller)
      end

      # As #deployed_as, for a task that runs outside of Syskit's control
      # (started by hand, or by another system): Syskit configures and
      # starts it once it is there. The plan says "unmanaged".
      def deployed_as_unmanaged(name, on: nil) # rubocop:disable Lint/UnusedMethodArgument
        declare_deployment(name, true, Location.of_caller)
      end

      # The deployment declared with #deployed_as, or nil.
      attr_reader :declared_deployment

      # Takes over what +requirements+ (given as +using:+) ask of the
      # driver: its configuration sections, deployment hints, deployment.
      def adopt_requirements(requirements)
        with_conf(*requirements.conf) if requirements.conf_given?
        prefer_deployed_tasks(*requirements.deployment_hints) unless requirements.deployment_hints.empty?
        @declared_deployment = requirements.deployment if requirements.deployment
        self
      end

      # The slave device +name+: a service of the driver declared +slave_of:+
      # the service driving this device (+driver_for Camera, as: 'left',
      # slave_of: 'stereo'+), registered when the driver is known. With
      # +as:+, +name+ is a dynamic service of the driver and the slave
      # +as+ is made from it, with +options+ for its block.
      #
      # When the driver is known as the device is declared, the slave is
      # bound to its service right away (see #bind_slaves_early).
      def slave(name, as: nil, **options)
        location = Location.of_caller
        if as
          early_bind(dynamic_slave(name.to_s, as.to_s, options, location))
        elsif (existing = find_slave(name))
          existing.claim(location)
        else
          early_bind(register_slave(SlaveDeviceInstance.new(self, check_slave_name(name.to_s, location),
                                                            location: location)))
        end
      end

      # Registers the slave services of +driver+, the driver known as the
      # device is declared, as this device's slaves, bound to their
      # services: as in Syskit, they exist from the declaration on
      # (+device(Stereo, as: 'cam').left_dev+, +cam.slave('left').service+).
      # #resolve_slaves settles them on the driver chosen once all is loaded.
      def bind_slaves_early(driver)
        return if @slaves_resolved

        @early_driver = driver
        driver.driver_services_for(model).each do |srv|
          driver.each_slave_data_service(srv) do |slave_srv|
            slave = find_slave(slave_srv.name) ||
                    register_slave(SlaveDeviceInstance.new(self, slave_srv.name, location: declared_at, implicit: true))
            slave.bind_early(driver)
          end
        end
      end

      # Slave devices by name (+left+ for +stereo.left+).
      def slaves
        @slaves || NO_SLAVES
      end

      # Enumerates the slave devices, in the order they were registered.
      def each_slave(&)
        slaves.each_value(&)
      end

      def find_slave(name)
        slaves[name.to_s]
      end

      def has_slave?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        slaves.key?(name.to_s)
      end

      # The task arguments that bind the driver's services to this device
      # (+gps_dev: device+), once the driver is known.
      #
      # Generation asks for them several times per device: they are made
      # once per driver (frozen), again if the driver changes.
      def driver_arguments
        driver = driver_model
        unless @driver_arguments_of.equal?(driver)
          @driver_arguments_of = driver
          @driver_arguments = { driver.argument_name => self }.freeze
        end
        @driver_arguments
      end

      # What the device asks of its driver (Syskit's +device.requirements+):
      # the driver model, with the arguments that bind it to the device.
      def requirements
        InstanceRequirements.new([driver_model.component_model],
                                 device: self, arguments: driver_arguments, declared_at: declared_at)
      end

      # Syskit's +device.instanciate(plan)+: the driver task of the device,
      # added to +plan+ (see InstanceRequirements#instanciate).
      def instanciate(plan, context = DependencyInjectionContext::EMPTY, **options)
        requirements.instanciate(plan, context, **options)
      end

      # Nil: a device declared in a robot block is its own master.
      def master_device; end

      # The name devices are known by in the robot (+gps+; +stereo.left+
      # for a slave).
      def full_name
        name
      end

      # +name[Model]+, as Syskit shows devices.
      def short_name
        "#{name}[#{model.short_name}]"
      end

      # The device model and the models it provides (see
      # Models::DataServiceModel#each_fullfilled_model).
      def each_fullfilled_model(&)
        model.each_fullfilled_model(&)
      end

      # Whether the device is attached to +bus+ (a bus or its name).
      def attached_to?(bus)
        return false unless self.bus

        bus.respond_to?(:to_str) ? self.bus.name == bus.to_str : self.bus.equal?(bus)
      end

      # Registers the slaves of the driver's services and makes the ones
      # asked for with #slave, once the driver is known; raises for a
      # slave the driver cannot serve. The driver's slaves come first, in
      # the order of its services (Syskit registers them with the device),
      # then the ones made from dynamic services, in the order asked.
      def resolve_slaves
        return if @slaves_resolved || !driver_resolved?

        @slaves_resolved = true
        known = slaves
        # Most drivers have no slave services, and most devices no slaves.
        task_model = driver_model.component_model
        return if known.empty? && task_model.slave_services.empty?

        @slaves = nil
        task_model.each_slave_data_service(driver_model) do |slave_srv|
          register_slave(known[slave_srv.name] ||
                         SlaveDeviceInstance.new(self, slave_srv.name, location: declared_at, implicit: true))
        end
        # Slaves asked for that the driver does not have are errors
        # (SlaveDeviceInstance#resolve); the driver's own are all registered above.
        known.each_value { |slave| register_slave(slave) unless slave.implicit? || find_slave(slave.name) }
      end

      private

      def declare_deployment(name, unmanaged, location)
        @declared_deployment = DeclaredDeployment.declare(name, unmanaged, location,
                                                          owner: self, hint: "write deployed_as('#{self.name}')")
        self
      end

      def dynamic_slave(dynamic, as, options, location)
        existing = find_slave(as)
        return existing if existing && existing.dynamic_service_name == dynamic && existing.dynamic_options == options

        check_slave_name(as, location)
        register_slave(SlaveDeviceInstance.new(self, as, location: location, dynamic: dynamic, options: options))
      end

      def check_slave_name(name, location)
        if (other = find_slave(name))
          raise DeclarationError.new("#{self} already has a slave named '#{name}' (#{other.declared_at})",
                                     location: location, hint: "give this one another name with as: 'other_name'")
        end
        return name if name.match?(/\A[a-z_][a-zA-Z0-9_]*\z/)

        raise DeclarationError.new("'#{name}' is not a valid slave device name",
                                   location: location, hint: "slave names are lower-case identifiers, e.g. 'left'")
      end

      # +<slave>_dev+ on the device (and on its profile action) gives the
      # slave, as Syskit's +master.left_dev+.
      def register_slave(slave)
        slave.resolve if @slaves_resolved
        (@slaves ||= {})[slave.name] = slave
        define_singleton_method("#{slave.name}_dev") { slave }
        robot.register_slave_device(slave)
        robot.profile&.slave_registered(slave)
        slave
      end

      # Binds a slave asked for with #slave to the driver known at
      # declaration, when there is one and the app is still loading.
      def early_bind(slave)
        slave.bind_early(@early_driver) if @early_driver && !@slaves_resolved
        slave
      end
    end

    class MasterDeviceInstance
      include MasterDevice
    end
  end
end
