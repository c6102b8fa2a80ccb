# frozen_string_literal: true

require 'syskit/robot/robot_lookups'

module Syskit
  module Robot
    # The devices and buses of a profile's robot, in declaration order.
    class Definition
      include RobotLookups

      DEVICE_OPTIONS = %i[client_to_bus bus_to_client].freeze

      attr_reader :profile

      # +profile+: the profile whose robot block declares it; none for a
      # robot made alone (+Syskit::Robot::RobotDefinition.new+ in a test).
      def initialize(profile = nil)
        @profile = profile
        @devices = {}
        @used = []
        @declaring = false
      end

      # The devices of this robot by name, as Syskit's +robot.devices['gps']+:
      # those of the robots it uses (see #use_robot), then its own, in
      # declaration order.
      def devices
        return @devices if @used.empty?

        @used.map(&:devices).reduce({}, :merge).merge(@devices)
      end

      # Makes the devices of +robot+ (a used profile's) devices of this one.
      def use_robot(robot)
        @used << robot unless robot.equal?(self) || @used.include?(robot)
      end

      # Evaluates a robot block's declarations (see Device#read_attribute).
      def declaring
        previous = @declaring
        @declaring = true
        yield
      ensure
        @declaring = previous
      end

      # Whether a robot block of this robot is being evaluated.
      def declaring?
        @declaring
      end

      # Declares a device (+klass+ Device) or a bus (ComBus); +bus+ is the
      # bus of the enclosing +through+ block, if any.
      def add_device(klass, model, name, using:, options:, location:, bus: nil)
        name = check_name(name, location)
        check_model(klass, model, location)
        given = using
        requirements = using if using.is_a?(InstanceRequirements)
        using = driver_task_model(using, location)
        check_using(using, location)
        check_device_options(options, bus, name, location)

        device = device_class(klass, model, bus).new(self, name, model, using, location)
        device.adopt_requirements(requirements) if requirements
        bind_driver_service(device, given)
        @devices[name] = device
        if bus
          attach_to_bus(device, bus, location, options.fetch(:client_to_bus, true), options.fetch(:bus_to_client, true))
        end
        profile&.define_device_action(device)
        driver = declared_driver(device)
        device.bind_slaves_early(driver) if driver
        device
      end

      # Registers a slave device by its full name too, as Syskit does
      # (+robot.devices['stereo.left']+).
      def register_slave_device(slave)
        @devices[slave.full_name] = slave
      end

      # Attaches +device+ to +bus+ (a ComBus or its name).
      def attach(device, bus, location:, client_to_bus: true, bus_to_client: true)
        attach_to_bus(device, bus, location, client_to_bus, bus_to_client)
      end

      # Resolves the model and driver of every device; returns the errors.
      def resolve(index)
        each_master_device.filter_map do |device|
          index.resolve(device)
          nil
        rescue Syskit::Error => e
          e
        end
      end

      # Bus models whose attached-device configuration defines +method_name+.
      def app_bus_models_defining(method_name)
        defining = lambda do |models|
          models.uniq.select { |m| m.attached_device_configuration_modules.any? { |c| c.method_defined?(method_name) } }
        end
        own = defining.call(each_master_device.grep(ComBus).map(&:model))
        # A robot without buses (a test's stub robot): any bus model loaded.
        own.empty? ? defining.call(Syskit::ComBus.each_submodel.to_a).sort_by(&:name) : own
      end

      def to_s
        profile ? "robot of #{profile}" : 'robot'
      end

      private

      # #attach, by position: a device declared in a through block is
      # attached without a keyword hash made for it.
      def attach_to_bus(device, bus, location, client_to_bus, bus_to_client)
        bus = find_bus(bus, location)
        if device.attached?
          raise DeclarationError.new("#{device} is already attached to #{device.bus}",
                                     location: location, hint: 'a device is attached to one bus')
        end
        if !client_to_bus && !bus_to_client
          raise DeclarationError.new(
            "#{device} would neither read from nor write to #{bus} (client_to_bus: false, bus_to_client: false)",
            location: location, hint: 'drop one of the two options, or do not attach the device'
          )
        end

        check_cycle(device, bus, location)
        device.attached(bus, client_to_bus, bus_to_client)
        begin
          device.check_combus_attachment(location)
        rescue Syskit::Error
          device.detached
          raise
        end
        bus.add_attached_device(device)
      end

      def check_device_options(options, bus, name, location)
        return if options.empty?

        if options.any? { |key, _| !DEVICE_OPTIONS.include?(key) }
          raise unknown_options(options.keys - DEVICE_OPTIONS, location)
        end
        return if bus

        raise DeclarationError.new(
          "#{options.keys.map { |k| "#{k}:" }.join(', ')} only applies to devices attached to a bus",
          location: location, hint: "declare #{name} in a through 'bus_name' do ... end block"
        )
      end

      # +using:+ a driver's service chooses the service that drives the
      # device, as in Syskit.
      def bind_driver_service(device, using)
        device.driver_model = using if using.is_a?(Models::BoundDataService) && device.model_resolved?
      end

      # The driver of +device+ as far as it is known while the device is
      # declared: +using:+, else the one driver of its model loaded so far.
      # Its slaves are bound to it right away, as Syskit does; the app
      # settles the driver once everything is loaded (DriverIndex).
      def declared_driver(device)
        return unless device.model_resolved?

        drivers = device.using ? [device.using] : loaded_drivers(device.model)
        driver = drivers.first if drivers.size == 1
        # Most drivers serve no slaves: nothing to bind then.
        driver if driver&.serves_slaves? && !driver.driver_services_for(device.model).empty?
      end

      def loaded_drivers(model)
        app = Syskit.app
        app ? app.orogen.current_driver_index.drivers_for(model) : []
      end

      # The class for a device of +model+ on +bus+: one that already includes
      # the configuration modules they add, when they are known now.
      def device_class(klass, model, bus)
        return klass unless model.is_a?(Models::DeviceModel)

        klass.including(model.device_configuration_modules,
                        bus ? bus.model.attached_device_configuration_modules : MasterDeviceInstance::NO_MODULES)
      end

      def check_name(name, location)
        if name.nil?
          raise DeclarationError.new('a device needs a name',
                                     location: location, hint: "write device(Model, as: 'name')")
        end
        name = name.to_s
        # Any identifier, as in Syskit (+as: 'COM'+ gives +COM_dev+).
        unless name.match?(/\A[A-Za-z_]\w*\z/)
          raise DeclarationError.new("'#{name}' is not a valid device name",
                                     location: location,
                                     hint: "device names are identifiers, usually lower-case, e.g. as: 'gps'")
        end
        if (other = @devices[name])
          at = " at #{other.declared_at}" if other.respond_to?(:declared_at)
          raise DeclarationError.new("a device named '#{name}' is already declared#{at}",
                                     location: location, hint: 'give each device its own name')
        end

        name
      end

      def check_model(klass, model, location)
        if klass <= ComBus
          return if model.is_a?(Models::ComBusModel)

          raise DeclarationError.new("com_bus expects a bus model (com_bus_type), got #{describe(model)}",
                                     location: location, hint: 'declare other devices with device')
        end
        if model.is_a?(Models::ComBusModel)
          raise DeclarationError.new("#{model} is a communication bus",
                                     location: location, hint: "declare it with com_bus #{model}, as: 'name'")
        end
        return if model.is_a?(Models::DeviceModel) || (model.is_a?(Class) && model <= TaskContext && model.spec)

        hint = if model.is_a?(Models::DataServiceModel)
                 'declare the hardware with device_type and make it provide this service'
               else
                 'pass a model declared with device_type, e.g. device(Devices::GPS::Ublox::F9, as: \'gps\')'
               end
        raise DeclarationError.new(
          "device expects a device model (device_type) or its driver task model, got #{describe(model)}",
          location: location, hint: hint
        )
      end

      # +using:+ names the driver by its task model, or by requirements of
      # it (+Task.with_dynamic_service(...)+, +Task.with_conf(...)+, as
      # Syskit accepts), or by one of its services (+Task.gps_srv+): the
      # driver model (the requirements the device takes over are +using+
      # itself).
      def driver_task_model(using, location)
        case using
        when Models::BoundDataService then using.task_model
        when InstanceRequirements
          unless using.arguments.empty? && using.selections.empty? && !using.device
            raise DeclarationError.new(
              'using: takes a driver task model, or its with_conf, prefer_deployed_tasks and deployed_as; ' \
              "got #{using}", location: location,
                              hint: 'give the device its settings with chained calls (.with_conf, .period, ...)'
            )
          end
          using.component_model || using
        else using
        end
      end

      def check_using(using, location)
        return if using.nil? || (using.is_a?(Class) && using <= TaskContext && using.spec)

        raise DeclarationError.new("using: expects a driver task model, got #{describe(using)}",
                                   location: location, hint: 'write using: OroGen.library.Task')
      end

      def describe(model)
        case model
        when Models::DataServiceModel then "#{model} (a #{model.kind})"
        else model.inspect
        end
      end

      def unknown_options(unknown, location)
        DeclarationError.new(
          "unknown option(s) #{unknown.map { |k| "#{k}:" }.join(', ')}" \
          "#{Naming.did_you_mean(unknown.first, %i[as using] + DEVICE_OPTIONS)}",
          location: location,
          hint: 'device takes as:, using:, and, on a bus, client_to_bus: and bus_to_client:; ' \
                'configure the rest with chained calls (.with_conf, .period, ...)'
        )
      end

      def find_bus(bus, location)
        return bus if bus.is_a?(ComBus)

        found = @devices[bus.to_s]
        return found if found.is_a?(ComBus)

        buses = each_master_device.grep(ComBus).map(&:name)
        what = found ? "#{found} is not a communication bus" : "no bus named '#{bus}'"
        hint = if buses.empty?
                 "declare it first: com_bus Model, as: '#{bus}'"
               else
                 "buses of this robot: #{buses.join(', ')}"
               end
        raise UnknownName.new("#{what}#{Naming.did_you_mean(bus, buses)}", location: location, hint: hint)
      end

      def check_cycle(device, bus, location)
        current = bus
        while current
          raise cycle_error(device, bus, location) if current.equal?(device)

          current = current.bus
        end
      end

      def cycle_error(device, bus, location)
        chain = [device, bus]
        chain << chain.last.bus until chain.last.equal?(device)
        NetworkError.new("attaching #{device} to #{bus} makes a cycle: #{chain.map(&:name).join(' -> ')}",
                         location: location, hint: 'a bus cannot be attached through itself')
      end
    end
  end
end
