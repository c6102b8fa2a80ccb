# frozen_string_literal: true

module Syskit
  module Models
    # What a task model drives: its driver services (master and slave), and
    # the device models they drive. Part of TaskModel (uses its cache).
    module DriverServices
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
