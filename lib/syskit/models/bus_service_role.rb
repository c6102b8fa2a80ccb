# frozen_string_literal: true

module Syskit
  module Models
    # What a bus's services add to a data service: port aliases and roles.
    # Part of DataServiceModel.
    module BusServiceRole
      # What users may write for a bus client's ports in port mappings (the
      # seed's disambiguation example maps 'bus_in' and 'bus_out').
      CLIENT_PORT_ALIASES = { 'bus_in' => 'from_bus', 'bus_out' => 'to_bus' }.freeze

      # For the seven services of a bus model: the bus, and the service's role
      # (:bus, :bus_in, :client_in, ...).
      attr_accessor :bus_model, :bus_role

      # The port called +name+ in mappings (a port name or one of its aliases).
      def port_name_for(name)
        return name if ports.key?(name)

        aliased = CLIENT_PORT_ALIASES[name] if bus_role.to_s.start_with?('client')
        aliased if aliased && ports.key?(aliased)
      end

      # Whether a task providing this service drives a bus (BusSrv, BusInSrv...).
      def bus_driver_service?
        bus_role && !bus_role.to_s.start_with?('client')
      end

      # The device (or bus) a task providing this service drives, if any.
      def driven_device_model
        return bus_model if bus_driver_service?

        self if is_a?(DeviceModel)
      end
    end
  end
end
