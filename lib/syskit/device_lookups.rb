# frozen_string_literal: true

require 'syskit/device_enumeration'

module Syskit
  # What a driver's configure method (and a test) asks a task about the
  # devices it drives, under Syskit's names:
  #
  #   def configure
  #     super
  #     each_master_device { |dev| ... }          # the devices it drives
  #     dev = find_device_attached_to('left')     # by service name, model or service
  #     each_attached_device { |dev| ... }        # on a bus driver: the devices it serves
  #   end
  #
  # each_master_device enumerates the devices the task drives (the devices
  # of its master driver services, each once), each_slave_device their
  # slaves (DeviceEnumeration).
  module DeviceLookups
    include DeviceEnumeration

    NO_DEVICES = [].freeze
    private_constant :NO_DEVICES

    # Enumerates the buses it drives.
    def each_com_bus_device(&block)
      return enum_for(__method__) unless block

      devices.each { |device| yield device if device.com_bus? }
    end

    # On a bus driver: the devices it serves, in declaration order. That is
    # every device declared on the bus, unless the bus model dispatches
    # lazily (then, those whose tasks are in the network); see
    # each_declared_attached_device for the declared ones.
    def each_attached_device(&block)
      return enum_for(__method__) unless block

      (@attached_devices || NO_DEVICES).each(&block)
    end

    # Records that this bus driver serves +device+ (the generator's Buses
    # step, once per device).
    def attach_device(device)
      (@attached_devices ||= []) << device
    end

    # Syskit's +bus_task.attach(device_task)+: this bus driver serves the
    # devices +device_task+ drives that are attached to one of its buses,
    # each through a service of its own named after the device (an
    # instance of its bus model's com_bus dynamic service, see
    # Models::ComBusModel#declare_attachment_service). Returns the devices
    # newly served.
    def attach(device_task)
      buses = devices.select(&:com_bus?)
      device_task.devices.select do |device|
        bus = buses.find { |b| device.attached_to?(b) }
        next false if each_attached_device.include?(device) || !bus

        require_attachment_service(bus, device)
        attach_device(device)
      end
    end

    # The device bound to +service+: a service of the task model, its (full)
    # name, a service model it provides exactly once, or nothing when the
    # task drives one device. A slave service gives the slave device.
    def find_device_attached_to(service = nil)
      service = service_for_device_lookup(service, Location.of_caller)
      return arguments[service.argument_name] if service.master?

      find_device_attached_to(service.master)&.find_slave(service.name)
    end

    # The driver services through which the task drives +device+ (for a
    # slave device, the slave services of its master's services).
    def find_all_driver_services_for(device)
      master = device.master_device
      return model.driver_services.select { |srv| arguments[srv.argument_name].equal?(device) } unless master

      find_all_driver_services_for(master).filter_map do |srv|
        model.find_service("#{srv.full_name}.#{device.name}")
      end
    end

    private

    def require_attachment_service(bus, device)
      dynamic = bus.model.dynamic_service_name
      return unless model.find_dynamic_service(dynamic)

      require_dynamic_service(dynamic, as: device.name, bus_to_client: device.bus_to_client?,
                                       client_to_bus: device.client_to_bus?)
    end

    def service_for_device_lookup(service, location)
      case service
      when Models::BoundDataService then service
      when BoundDataService then service.model
      when nil then only(model.driver_services, 'driver service', location)
      when Models::DataServiceModel then only(model.services_fulfilling(service), "service of #{service}", location)
      else model.find_service(service.to_s) || raise(unknown_service(service.to_s, location))
      end
    end

    def unknown_service(name, location)
      ConfigurationError.new(
        "#{model.name} has no service named '#{name}'#{Naming.did_you_mean(name, model.services.keys)}",
        location: location, hint: "its services: #{model.services.keys.sort.join(', ')}"
      )
    end

    def only(services, what, location)
      return services.first if services.size == 1

      names = services.map(&:full_name).sort
      hint = "name one: find_device_attached_to('#{names.first}')"
      hint = "its services: #{model.services.keys.sort.join(', ')}" if services.empty?
      raise ConfigurationError.new(
        "#{model.name} has #{services.empty? ? "no #{what}" : "several #{what}s: #{names.join(', ')}"}",
        location: location, hint: hint
      )
    end
  end

  class TaskContext
    include DeviceLookups
  end
end
