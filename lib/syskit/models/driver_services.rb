# frozen_string_literal: true

module Syskit
  module Models
    # What a task model drives: its driver services (master and slave), and
    # the device models they drive. Part of Models::Component (uses its cache).
    module DriverServices
      # Declares that this component drives devices of +model+; the device is given
      # to the component as its +<as>_dev+ argument. Ports of the device model are
      # bound by name and type, or by +'device_port' => 'task_port'+ mappings
      # (keywords or a hash). +slave_of: 'master'+ makes it a slave device
      # of the master service's device (see Robot::SlaveDeviceInstance).
      def driver_for(model, mappings = {}, as: nil, slave_of: nil, **more)
        location = Location.of_caller
        unless model.is_a?(DeviceModel)
          hint = if model.is_a?(DataServiceModel) then "#{model} is a data service: use provides #{model}, as: 'name'"
                 else NotAModel.hint('driver_for', model, location)
                 end
          raise DeclarationError.new("driver_for expects a device or bus model, got #{model.inspect}",
                                     location: location, hint: hint)
        end

        as ||= Naming.underscore(model.name.to_s.split('::').last)
        service = add_service(as, model, mappings.merge(more), location, slave_of: slave_of)
        model.declare_attachment_service(self) if model.is_a?(ComBusModel)
        service
      end

      # Whether +name+ is the argument holding the device of a driver
      # service (+gps_dev+ for +driver_for Gps, as: 'gps'+).
      def device_argument?(name)
        driver_services.any? { |srv| srv.argument_name == name }
      end

      # Services through which this task drives a device or a bus (Syskit's
      # master driver services: slave services are served with their master).
      def driver_services
        cached(:driver_services) { services.values.select { |srv| srv.master? && srv.driven_device_model }.freeze }
      end

      # Enumerates {#driver_services}, as Syskit names it.
      def each_master_driver_service(&)
        driver_services.each(&)
      end

      # Enumerates the driver services of buses.
      def each_com_bus_driver_service(&block)
        return enum_for(__method__) unless block

        driver_services.each { |srv| yield srv if srv.driven_device_model.is_a?(ComBusModel) }
      end

      # Enumerates the services declared +slave_of:+ +master+ (a service or
      # its full name).
      def each_slave_data_service(master, &block)
        return enum_for(__method__, master) unless block

        name = master.respond_to?(:full_name) ? master.full_name : master.to_s
        slave_services.each { |srv| yield srv if srv.master.full_name == name }
      end

      # The services declared +slave_of:+ another, in declaration order.
      def slave_services
        cached(:slave_services) { services.values.reject(&:master?).freeze }
      end

      # Whether the devices this task drives may have slave devices: it has
      # slave services, or dynamic services to make them from.
      def serves_slaves?
        cached(:serves_slaves) { !slave_services.empty? || !dynamic_service_names.empty? }
      end

      # Those of {#driver_services} that can drive a device of +device_model+:
      # the service's device model must be it or provide it.
      def driver_services_for(device_model)
        cached(:driver_services_for, device_model) do
          driver_services.select { |srv| srv.driven_device_model.fullfills?(device_model) }.freeze
        end
      end

      def driven_device_models
        driver_services.map(&:driven_device_model).uniq
      end

      # The device models a `device(ThisTask, ...)` declaration can mean
      # (buses are declared with com_bus and their model).
      def declarable_device_models
        driven_device_models.grep_v(ComBusModel)
      end
    end
  end
end
