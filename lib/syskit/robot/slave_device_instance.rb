# frozen_string_literal: true

module Syskit
  module Robot
    # A device that another device's driver serves (Syskit's
    # SlaveDeviceInstance), through a service of the driver declared
    # +slave_of:+ the service driving the master: the left camera of a
    # stereo camera, a link a simulated model exports. Its driver and task
    # are its master's; it is named after it (+stereo.left+) and gives the
    # profile the action +stereo.left_dev+.
    #
    # Its period, burst and sample_size are its own, or else its master's.
    # What configures the driver (with_conf, prefer_deployed_tasks,
    # deployed_as, attach_to) is declared on the master.
    class SlaveDeviceInstance < MasterDeviceInstance
      attr_reader :master_device, :service, :dynamic_service_name, :dynamic_options

      # Not Device#initialize: a slave has no model of its own until its
      # master's driver is known.
      def initialize(master, name, location:, dynamic: nil, options: {}, implicit: false) # rubocop:disable Lint/MissingSuper
        @robot = master.robot
        @implicit = implicit
        @master_device = master
        @name = name
        @declared_at = location
        @dynamic_service_name = dynamic
        @dynamic_options = options.freeze
        @dsl_attributes = {}
        @client_to_bus = true
        @bus_to_client = true
        @created_ports = NO_PORTS
      end

      NO_PORTS = [].freeze
      private_constant :NO_PORTS

      # The ports a dynamic service creates on the driver for this slave.
      attr_reader :created_ports

      # Whether the slave was registered from a slave service of the driver
      # rather than asked for with +slave(name)+.
      def implicit?
        @implicit
      end

      # Asked for with +slave(name)+ at +location+: from then on a driver
      # without this slave is an error there.
      def claim(location)
        if @implicit
          @implicit = false
          @declared_at = location
        end
        self
      end

      # Binds the slave to its service on +driver+, the master's (or makes
      # it from the dynamic service); raises when the driver has none.
      def resolve(driver = master_device.driver_model.component_model)
        return if @service && @bound_driver.equal?(driver)

        service, ports = dynamic_service_name ? instantiate(driver) : [static_service(driver), NO_PORTS]
        @bound_driver = driver
        @service = service
        @created_ports = ports.freeze
        configure_with(service.model.device_configuration_modules) if service.model.is_a?(Models::DeviceModel)
      end

      # Binds the slave to +driver+, the driver known as its master is
      # declared, when that driver serves it; otherwise it stays unbound
      # until the app is loaded, where #resolve says what is wrong.
      def bind_early(driver)
        resolve(driver)
      rescue Syskit::Error
        nil
      end

      def model
        return service.model if service

        raise DriverError.new("the model of #{self} is not resolved yet", location: declared_at)
      end

      def model_resolved?
        !service.nil?
      end

      def driver_model
        master_device.driver_model
      end

      def driver_resolved?
        master_device.driver_resolved?
      end

      def full_name
        "#{master_device.name}.#{name}"
      end

      def conf
        master_device.conf
      end

      def conf_location
        master_device.conf_location
      end

      def deployment_hints
        master_device.deployment_hints
      end

      def period(seconds = nil)
        seconds.nil? ? super() || master_device.period : super
      end

      def burst(count = nil)
        count.nil? ? super() || master_device.burst : super
      end

      def sample_size(size = nil)
        size.nil? ? super() || master_device.sample_size : super
      end

      MASTER_ONLY = %w[with_conf prefer_deployed_tasks attach_to deployed_as deployed_as_unmanaged slave].freeze
      MASTER_ONLY.each do |method_name|
        define_method(method_name) do |*_args, **_options|
          raise DeclarationError.new(
            "#{method_name} on #{self}: a slave device is served by the driver of #{master_device}",
            location: Location.of_caller, hint: "call #{method_name} on #{master_device.name} instead"
          )
        end
      end

      # The same slave: the slave of this name of the same master device.
      def ==(other)
        other.kind_of?(SlaveDeviceInstance) && other.master_device == master_device && other.name == name # rubocop:disable Style/ClassCheck
      end
      alias eql? ==

      def hash
        [master_device, name].hash
      end

      def to_s
        "device '#{full_name}'"
      end

      def inspect
        "#<Syskit::Robot::SlaveDeviceInstance #{full_name}>"
      end

      private

      def static_service(driver)
        masters = driver.driver_services_for(master_device.model)
        found = masters.lazy.filter_map { |srv| driver.find_service("#{srv.full_name}.#{name}") }.first
        return found if found

        slaves = masters.flat_map { |srv| driver.each_slave_data_service(srv).map(&:name) }
        hint = "its slave services: #{slaves.join(', ')}"
        if slaves.empty?
          hint = "declare it in #{driver.name}'s extension: provides Model, as: '#{name}', " \
                 "slave_of: '#{masters.first&.name}'"
        end
        raise DeclarationError.new(
          "#{driver.name} has no slave service '#{name}' for #{master_device}#{Naming.did_you_mean(name, slaves)}",
          location: declared_at, hint: hint
        )
      end

      def instantiate(driver)
        driver.fetch_dynamic_service(dynamic_service_name, declared_at, "to make #{self} from")
              .instance_for(name, dynamic_options, declared_at)
      end

      def chainable_methods
        super - MASTER_ONLY
      end
    end
  end
end
