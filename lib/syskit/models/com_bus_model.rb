# frozen_string_literal: true

require 'syskit/models/device_model'

module Syskit
  module Models
    # A communication bus model (+com_bus_type 'CAN', message_type: T+): a
    # device whose driver multiplexes the I/O of the devices attached to it.
    #
    # Every bus model defines seven services, all of its message type:
    # BusBaseSrv; BusSrv, BusInSrv, BusOutSrv for bus drivers (+to_bus+ input,
    # +from_bus+ output); ClientSrv, ClientInSrv, ClientOutSrv for the drivers
    # of attached devices (+from_bus+ input, +to_bus+ output).
    class ComBusModel < DeviceModel
      SERVICES = %w[BusBaseSrv BusSrv BusInSrv BusOutSrv ClientSrv ClientInSrv ClientOutSrv].freeze

      attr_reader :message_type

      def self.kind
        'communication bus'
      end

      def initialize(message_type: nil, **options)
        super(**options)
        @attached_device_configuration_module = nil
        @lazy_dispatch = false
        @override_policy = true
        self.message_type = message_type if message_type
      end

      # +com_bus_type 'CAN', message_type: T, lazy_dispatch: true,
      # override_policy: false+ (the defaults are false and true).
      def apply_options(message_type: nil, lazy_dispatch: false, override_policy: true)
        self.message_type = message_type if message_type
        @lazy_dispatch = lazy_dispatch ? true : false
        @override_policy = override_policy ? true : false
      end

      # Whether the bus driver serves only the attached devices whose tasks
      # are in the network (Syskit's lazy dispatch). By default, as in
      # Syskit, it serves every device declared on the bus: a bus planned
      # alone gets the per-device ports of all of them.
      def lazy_dispatch?
        @lazy_dispatch
      end

      # Syskit's +lazy_dispatch = true+ (see #lazy_dispatch?).
      def lazy_dispatch=(value)
        @lazy_dispatch = value ? true : false
      end

      # Whether the bus driver's inputs get a buffered policy even when they
      # do not declare needs_reliable_connection (true by default, as in
      # Syskit).
      def override_policy?
        @override_policy
      end

      def message_type=(type)
        location = Location.of_caller
        type = Models.resolve_type(type, location)
        if @message_type && @message_type != type
          raise DeclarationError.new(
            "#{self} has message type #{@message_type}, cannot change it to #{type}",
            location: location, hint: 'a bus model has a single message type'
          )
        end
        return if @message_type

        @message_type = type
        define_services
      end

      SERVICES.each do |srv|
        define_method(Naming.underscore(srv)) { const_get(srv, false) if message_type }
      end

      # Adds the methods defined in the block (e.g. +dsl_attribute :can_id+) to
      # every device attached to a bus of this model or of its sub-models.
      def extend_attached_device_configuration(&block)
        Arguments.block(block, statement: 'extend_attached_device_configuration',
                               example: 'extend_attached_device_configuration do dsl_attribute :can_id end')
        attached_device_configuration_module.module_eval(&block)
        attached_device_configuration_module
      end

      # The module this bus model's own extend_attached_device_configuration
      # blocks define (those of the models it provides are apart: see
      # #attached_device_configuration_modules).
      def attached_device_configuration_module
        @attached_device_configuration_module ||=
          DeviceConfigurationModule.new.tap { DataServiceModel.hierarchy_changed }
      end

      def attached_device_configuration_modules
        hierarchy_view(:attached_device_configuration_modules) do
          fullfilled_models.reverse.filter_map do |m|
            m.instance_variable_get(:@attached_device_configuration_module) if m.is_a?(ComBusModel)
          end
        end
      end

      def provides(model, mappings = {})
        if model.is_a?(ComBusModel) && model.message_type
          if message_type && message_type != model.message_type
            raise DeclarationError.new(
              "#{self} (message type #{message_type}) cannot provide #{model} " \
              "(message type #{model.message_type})",
              location: Location.of_caller, hint: 'a bus can only provide buses of the same message type'
            )
          end
          self.message_type = model.message_type
        end
        super
        link_services(model) if model.is_a?(ComBusModel) && model.message_type
        self
      end

      # The name of the dynamic service a driver of this bus has (Syskit's
      # +dynamic_service_name+): a bus task's +attach+ makes an instance
      # of it for each device it serves (see #declare_attachment_service).
      def dynamic_service_name
        'com_bus'
      end

      # Declares, on +driver_model+ (a task model that drives this bus),
      # the dynamic service whose instance, named after a device, is the
      # bus side of the device's link: a BusSrv, BusOutSrv or BusInSrv
      # (+bus_to_client:+, +client_to_bus:+ options) mapped to the ports
      # network generation uses too (Network::BusPorts.bus_port_of).
      def declare_attachment_service(driver_model)
        return if driver_model.find_dynamic_service(dynamic_service_name)

        bus_m = self
        driver_model.dynamic_service(self::BusBaseSrv, as: dynamic_service_name) do
          bus_m.attachment_service(self, options)
        end
      end

      # What the com_bus dynamic service's block does (see
      # #declare_attachment_service) in +context+, its instance's.
      def attachment_service(context, options)
        to_client, to_bus = attachment_directions(context, options)
        mappings = {}
        mappings['from_bus'] = attachment_port(context, :output, self::BusOutSrv, 'from_bus', context.name) if to_client
        mappings['to_bus'] = attachment_port(context, :input, self::BusInSrv, 'to_bus', "w#{context.name}") if to_bus
        srv_m = if to_client && to_bus then self::BusSrv
                elsif to_client then self::BusOutSrv
                else self::BusInSrv
                end
        context.provides(srv_m, mappings)
      end

      def finalize_declaration
        return if message_type || equal?(Syskit::ComBus)

        raise DeclarationError.new(
          "#{self} has no message type",
          location: declared_at,
          hint: "pass it: com_bus_type '#{name.to_s.split('::').last}', message_type: '/canbus/Message'"
        )
      end

      private

      # The +bus_to_client:+ and +client_to_bus:+ options, both required,
      # one of them true at least.
      def attachment_directions(context, options)
        directions = %i[bus_to_client client_to_bus].map { |key| options.fetch(key, nil) }
        return directions if directions.none?(&:nil?) && directions.any?

        raise DeclarationError.new(
          "the #{dynamic_service_name} service '#{context.name}' of a #{self} driver needs bus_to_client: and " \
          "client_to_bus:, one of them true (got #{options.slice(:bus_to_client, :client_to_bus)})",
          location: Location.of_caller,
          hint: "write require_dynamic_service('#{dynamic_service_name}', as: '#{context.name}', " \
                'bus_to_client: true, client_to_bus: true)'
        )
      end

      def attachment_port(context, direction, service_model, service_port, dynamic_name)
        model = context.component_model
        name, = Network::BusPorts.bus_port_of(model, direction, service_model, service_port, dynamic_name)
        return name if name

        raise DeclarationError.new(
          "#{model.name} has no #{direction} port to serve #{context.name} on a #{self}",
          location: Location.of_caller,
          hint: "declare dynamic_#{direction}_port(/^\\w+$/, '#{message_type}'), or provide #{service_model}"
        )
      end

      def define_services
        type = message_type
        base = service('BusBaseSrv') { nil }
        bus_in = service('BusInSrv') { input_port 'to_bus', type }
        bus_out = service('BusOutSrv') { output_port 'from_bus', type }
        bus = service('BusSrv') { nil }
        [bus_in, bus_out].each { |s| s.provides(base) }
        bus.provides(bus_in).provides(bus_out)

        client_in = service('ClientInSrv') { input_port 'from_bus', type }
        client_out = service('ClientOutSrv') { output_port 'to_bus', type }
        service('ClientSrv') { nil }.provides(client_in).provides(client_out)
      end

      def service(name, &)
        srv = DataServiceModel.new(location: declared_at, name: "#{self}::#{name}")
        const_set(name, srv)
        srv.instance_eval(&)
        srv.bus_model = self
        srv.bus_role = Naming.underscore(name.delete_suffix('Srv')).to_sym
        srv
      end

      # Our services provide the provided bus's, so drivers of a sub-bus are
      # drivers of the parent bus too.
      def link_services(model)
        SERVICES.each do |srv|
          parent = model.const_get(srv, false)
          const_get(srv, false).provides(parent, parent.ports.keys.to_h { |name| [name, name] })
        end
      end
    end
  end
end
