# frozen_string_literal: true

require 'syskit/robot/can_traffic'
require 'syskit/robot/dsl_attributes'
require 'syskit/robot/com_bus_client'

module Syskit
  module Robot
    # A device on a robot, declared in a profile's robot block:
    #
    #   device(Devices::GPS::Ublox::F9, as: 'gps')
    #     .prefer_deployed_tasks(/gps/).with_conf('default', 'rtk').period(0.1)
    #
    # Chainable calls configure it; bus attributes (+can_id+) come from the
    # modules of its device model and of the bus it is attached to.
    # Their values are kept by DslAttributes; its slaves and a deployment of
    # its own are MasterDevice's; a bus is a ComBus.
    class MasterDeviceInstance
      include CanTraffic::DeviceStatements
      include DslAttributes
      include ComBusClient

      DEFAULT_CONF = ['default'].freeze
      # What a device has before any prefer_deployed_tasks; the lists of
      # configuration modules of a device on no bus.
      NO_HINTS = [].freeze
      NO_MODULES = [].freeze

      attr_reader :name, :robot, :declared_at, :requested_model, :using, :bus,
                  :deployment_hints, :dsl_attributes, :client_to_bus, :bus_to_client

      # By position: one is made for every device declared, and keywords
      # given to +new+ cost a hash each.
      def initialize(robot, name, requested_model, using = nil, location = nil)
        @robot = robot
        @name = name
        @requested_model = requested_model
        @using = using
        @declared_at = location
        @conf = DEFAULT_CONF
        # Frozen, replaced when hints are added: requirements hand it out
        # as it is (see InstanceRequirements#deployment_hints).
        @deployment_hints = NO_HINTS
        @dsl_attributes = {}
        @client_to_bus = true
        @bus_to_client = true
        model = requested_model.is_a?(Models::DeviceModel) ? requested_model : single_driven_model
        assign_model(model) if model
      end

      def com_bus?
        false
      end

      # The device model (resolved once the app is loaded when the device was
      # declared with a driver task model).
      def model
        @model || raise(DriverError.new("the model of #{self} is not resolved yet", location: declared_at))
      end

      def model_resolved?
        !@model.nil?
      end

      # The driver's service that drives this device, once resolved (a
      # Models::BoundDataService, as Syskit's +driver_model+); its
      # +component_model+ is the driver's task model.
      def driver_model
        @driver_model || raise(DriverError.new("the driver of #{self} is not resolved yet", location: declared_at))
      end

      # Binds the device to its driver: the driver's service for it, or a
      # task model, whose first driver service for the device's model is
      # then chosen.
      def driver_model=(driver)
        @driver_model = driver.is_a?(Models::BoundDataService) ? driver : driver_service_of(driver)
      end

      def driver_resolved?
        !@driver_model.nil?
      end

      def driver_service_of(task_model)
        services = own_services(task_model.driver_services_for(model))
        return services.first if services.size == 1

        if services.empty?
          raise DriverError.new("#{task_model.name} does not drive #{model} (#{self})",
                                location: declared_at, hint: "declare driver_for #{model} in its extension file")
        end

        raise DriverError.new(
          "#{task_model.name} has several services that can drive #{self} (#{model}): " \
          "#{services.map(&:name).join(', ')}",
          location: declared_at,
          hint: "choose one with using: OroGen.#{task_model.name.sub('::', '.')}.#{services.first.name}_srv"
        )
      end

      def assign_model(model)
        @model = model
        configure_with(model.device_configuration_modules)
      end

      # The configuration sections applied to the driver, in order. As in
      # Syskit, the list replaces ['default']: write with_conf('default', 'x').
      def with_conf(*names)
        names = names.flatten if names.any?(Array)
        names = names.map(&:to_s) unless names.all?(String)
        if names.empty?
          raise DeclarationError.new('with_conf needs at least one section name',
                                     location: Location.of_caller, hint: "write with_conf('default', 'forward')")
        end

        @conf = names.freeze
        @conf_location = Location.of_caller
        self
      end

      # The sections, and where they were chosen.
      attr_reader :conf, :conf_location

      # Chooses among the deployed tasks that could run this device's driver:
      # names matching a regexp or equal to a string (or matched by ===).
      def prefer_deployed_tasks(*hints)
        hints = hints.flatten if hints.any?(Array)
        hints.each do |hint|
          next if Arguments.deployment_hint?(hint)

          raise DeclarationError.new("prefer_deployed_tasks expects regexps or names, got #{hint.inspect}",
                                     location: Location.of_caller, hint: 'write prefer_deployed_tasks(/forward/)')
        end
        # +hints+ is this call's own array: kept as it is by the first call
        # (frozen: see above).
        @deployment_hints = (@deployment_hints.empty? ? hints : @deployment_hints + hints).freeze
        @deployment_hints_location = Location.of_caller
        self
      end

      # Where prefer_deployed_tasks was last called.
      attr_reader :deployment_hints_location

      # Expected time between two messages of the device, in seconds.
      def period(seconds = nil)
        setting(:period, :@period, seconds, 'a positive number of seconds') { |v| v.is_a?(Numeric) && v.positive? }
      end

      # How many messages the device may send at once, beyond one per
      # period (0, Syskit's default, for none).
      def burst(count = nil)
        setting(:burst, :@burst, count, 'an integer, 0 or more') { |v| v.is_a?(Integer) && !v.negative? }
      end

      # Size of one message, for drivers that size their buffers.
      def sample_size(size = nil)
        setting(:sample_size, :@sample_size, size, 'a positive integer') { |v| v.is_a?(Integer) && v.positive? }
      end

      # Documentation of the device. As Syskit's dsl_attribute: no argument
      # reads it, +doc(text)+ sets it (anything with #to_str), +doc(nil)+
      # removes it. Without one, the robot block takes the comment lines
      # just above the +device+ statement.
      def doc(*text)
        return @doc if text.empty?

        value = text.first
        unless text.size == 1 && (value.nil? || value.respond_to?(:to_str))
          raise DeclarationError.new("invalid doc #{text.map(&:inspect).join(', ')} for #{self}",
                                     location: Location.of_caller, hint: 'doc takes a string, or nil to remove it')
        end

        @doc = value&.to_str
        self
      end

      # Attaches the device to a bus (the same as declaring it in a
      # +through+ block). +client_to_bus: false+ for read-only devices,
      # +bus_to_client: false+ for write-only ones; a string names the
      # driver's ClientSrv/ClientInSrv/ClientOutSrv service to use.
      def attach_to(bus, client_to_bus: true, bus_to_client: true)
        robot.attach(self, bus, client_to_bus: client_to_bus, bus_to_client: bus_to_client,
                                location: Location.of_caller)
        self
      end

      # Called by the robot once the attachment is checked.
      def attached(bus, client_to_bus, bus_to_client)
        @bus = bus
        @client_to_bus = client_to_bus
        @bus_to_client = bus_to_client
        configure_with(bus.model.attached_device_configuration_modules)
      end

      # Undoes #attached, for an attachment that turned out impossible.
      def detached
        @bus = nil
        @client_to_bus = true
        @bus_to_client = true
      end

      # A Device subclass that includes +modules+ (configuration methods of
      # device and bus models), made once per combination and kept by the
      # first module: devices declared with known model and bus get their
      # methods without a singleton class each.
      # +modules+ are the device model's, +bus_modules+ its bus model's.
      def self.including(modules, bus_modules = NO_MODULES)
        owner = modules.first || bus_modules.first
        return self unless owner

        classes = owner.instance_variable_get(:@device_classes) || owner.instance_variable_set(:@device_classes, {})
        # By class, then by each list of modules (looked up as given, kept
        # as frozen copies).
        by_modules = classes[self] ||= {}
        by_bus_modules = by_modules[modules] || (by_modules[modules.dup.freeze] = {})
        by_bus_modules[bus_modules] ||
          (by_bus_modules[bus_modules.dup.freeze] = Class.new(self) { (modules + bus_modules).each { include _1 } })
      end

      def attached?
        !bus.nil?
      end

      # Whether the driver writes to the bus / reads from the bus.
      def client_to_bus?
        client_to_bus != false
      end

      def bus_to_client?
        bus_to_client != false
      end

      def explain_missing(method_name)
        buses = robot.app_bus_models_defining(method_name)
        return explain_not_attached(method_name, buses) if buses.any? && !attached?

        ["#{self} has no '#{method_name}'#{Naming.did_you_mean(method_name, chainable_methods)}",
         "chainable calls on devices: #{chainable_methods.join(', ')}"]
      end

      # A bus attribute asked of a device on no bus: in a profile, it is
      # declared outside its bus's through block; in a test (a robot of no
      # profile), the stub device was made on no bus.
      def explain_not_attached(method_name, buses)
        message = "#{self} has no '#{method_name}': it is on no bus, and #{method_name} is for devices attached " \
                  "to a #{buses.map(&:name).join(' or ')} bus"
        hint =
          if robot.profile
            "declare #{name} in a through 'bus_name' do ... end block"
          else
            "in a test, make it on a stub bus: bus = syskit_stub_com_bus(#{buses.first.name}); " \
              "dev = syskit_stub_attached_device(bus).#{method_name}(...)"
          end
        [message, hint]
      end

      # The same device: the device of this name on the same robot (as
      # Syskit compares them, by what they answer to +robot+ and +name+).
      def ==(other)
        return false if SlaveDeviceInstance === other # rubocop:disable Style/CaseEquality -- the class, not what other says

        other.kind_of?(MasterDeviceInstance) && other.robot.equal?(robot) && other.name == name # rubocop:disable Style/ClassCheck
      end
      alias eql? ==

      def hash
        [robot, name].hash
      end

      def to_s
        "device '#{name}'"
      end

      def inspect
        "#<#{com_bus? ? 'Syskit::Robot::ComBus' : 'Syskit::Robot::MasterDeviceInstance'} #{name}>"
      end

      private

      # A bus driver's bus services (BusInSrv...) serve the bus too; its
      # driver service is the one of the bus model itself. Usually every
      # service is the device model's own: no list is made then.
      def own_services(services)
        return services if services.all? { |srv| srv.model.fullfills?(model) }

        own = services.select { |srv| srv.model.fullfills?(model) }
        own.empty? ? services : own
      end

      # Adds the methods of +modules+ that the device's class does not have.
      def configure_with(modules)
        modules.each { |mod| extend(mod) unless is_a?(mod) }
      end

      # The device model a driver task model stands for, when it is already
      # known (DriverIndex resolves the others, with errors, after loading).
      def single_driven_model
        return unless requested_model.is_a?(Class) && requested_model <= TaskContext

        models = requested_model.declarable_device_models
        models.first if models.size == 1
      end

      # Reads the setting +key+ (without +value+) or sets it, once the
      # block accepts +value+. Settings are instance variables (+ivar+)
      # rather than a hash: nearly every device has a period, and a hash
      # each is one more object.
      def setting(key, ivar, value, expected)
        return read_attribute(key, instance_variable_get(ivar), expected) if value.nil?

        unless yield(value)
          raise DeclarationError.new("invalid #{key} #{value.inspect} for #{self}",
                                     location: Location.of_caller, hint: "#{key} takes #{expected}")
        end

        instance_variable_set(ivar, value)
        self
      end

      def chainable_methods
        (%w[with_conf prefer_deployed_tasks deployed_as period burst sample_size doc attach_to slave frame] +
          singleton_class.ancestors.grep(Models::DeviceConfigurationModule)
                         .flat_map { |m| m.public_instance_methods(false).map(&:to_s) })
          .reject { |m| m.start_with?('__') }.uniq
      end
    end
  end
end
