# frozen_string_literal: true

module Syskit
  module Network
    # The ports that link an attached device's driver to its bus's driver.
    #
    # Bus side, per direction:
    # - a service the bus driver provides (BusSrv, BusInSrv, BusOutSrv): its
    #   single port serves every device;
    # - else a dynamic port pattern: a port per device, '<device>' for the
    #   frames the device receives, 'w<device>' for the ones it sends;
    # - else the driver's single port of the bus message type.
    # Device side: the ClientSrv/ClientInSrv/ClientOutSrv the driver
    # provides (named by the bus_to_client:/client_to_bus: options when there
    # are several), else its single port of the message type.
    class BusPorts
      # One per bus driver task (the one of +bus_task+); +expected+
      # collects the per-device ports it must create. Each call works on
      # one device: the instance keeps it while choosing its ports.
      def initialize(bus_task, expected)
        @bus_task = bus_task
        @expected = expected
      end

      # The bus driver's side of +device+'s link: its port to the device
      # (+bus_output+) and from it (+bus_input+), nil for a direction the
      # device does not use.
      def bus_side(device)
        @device = device
        @bus = device.bus
        @bus_model = @bus.model
        @type = @bus_model.message_type
        link = Context::BusLink.new(device, @bus_task)
        link.bus_output = bus_port(:output, @bus_model.bus_out_srv, 'from_bus', '') if device.bus_to_client?
        link.bus_input = bus_port(:input, @bus_model.bus_in_srv, 'to_bus', 'w') if device.client_to_bus?
        link
      end

      # The link of +device+, completed with the ports of its task.
      def link(device, device_task)
        link = bus_side(device)
        @device_task = device_task
        link.device_task = device_task
        if link.bus_output
          link.client_input = client_port(:input, @bus_model.client_in_srv, 'from_bus', 'bus_to_client')
        end
        if link.bus_input
          link.client_output = client_port(:output, @bus_model.client_out_srv, 'to_bus', 'client_to_bus')
        end
        link
      end

      # The port of the bus driver +model+ that serves one device in
      # +direction+, and whether it is a per-device port: the port of its
      # service of +service_model+ (BusInSrv...), else +dynamic_name+ when
      # a dynamic port pattern allows it, else its single port of the bus's
      # message type; nil when it has none. What network generation and a
      # bus task's +attach+ (the com_bus dynamic service) both use.
      def self.bus_port_of(model, direction, service_model, service_port, dynamic_name)
        name = service_port_of(model, service_model, service_port)
        return [name, false] if name

        per_device_port_of(model, direction, service_model, dynamic_name)
      end

      # The second half of #bus_port_of, for a driver without a service
      # port serving every device: +dynamic_name+ when a dynamic port
      # pattern allows it, else its single port of the bus's message type.
      def self.per_device_port_of(model, direction, service_model, dynamic_name)
        type = service_model.bus_model.message_type
        return [dynamic_name, true] if model.spec&.dynamic_port_for(direction, dynamic_name, type)

        single = model.static_ports_of(direction, type)
        [single.first.name, false] if single.size == 1
      end

      # The port of the bus driver +model+'s service of +service_model+
      # that serves every device, nil when it has none. Array#index, not
      # #find: asked twice per device, it allocates nothing.
      def self.service_port_of(model, service_model, service_port)
        services = model.services_fulfilling(service_model)
        found = services.index { |srv| srv.dynamic_service.nil? }
        services[found].task_port_for(service_model, service_port).name if found
      end

      private

      # The bus side's port for the device in +direction+; +prefix+ and the
      # device's name make its per-device port's name (made only when the
      # driver has no service port for every device).
      def bus_port(direction, service_model, service_port, prefix)
        shared = BusPorts.service_port_of(@bus_task.model, service_model, service_port)
        return shared if shared

        dynamic_name = prefix.empty? ? @device.name : "#{prefix}#{@device.name}"
        name, dynamic = BusPorts.per_device_port_of(@bus_task.model, direction, service_model, dynamic_name)
        raise no_bus_port(direction, dynamic_name) unless name

        @expected << Context::ExpectedPort.new(dynamic_name, direction, @type, @device) if dynamic
        name
      end

      def client_port(direction, service_model, service_port, option)
        model = @device_task.model
        wanted = @device.public_send(option)
        service = @device.combus_client_service(model, service_model, wanted.is_a?(String) ? wanted : nil,
                                                @bus, option)
        return service.task_port_for(service_model, service_port).name if service

        candidates = ports_of_type(model, direction)
        return candidates.first.name if candidates.size == 1

        raise no_client_port(direction, option) if candidates.empty?

        raise ambiguous_client_ports(direction, option, candidates, service_model)
      end

      def ports_of_type(model, direction)
        model.static_ports_of(direction, @type)
      end

      def no_bus_port(direction, dynamic_name)
        what = direction == :output ? "send the frames of #{@device} to it" : "receive the frames of #{@device}"
        NetworkError.new(
          "#{@bus_task.model.name}, the driver of #{@bus}, has no way to #{what}: " \
          "no #{direction == :output ? 'BusOutSrv/BusSrv' : 'BusInSrv/BusSrv'} service, no dynamic #{direction} " \
          "port matching '#{dynamic_name}' and no single #{direction} port of type #{@type}",
          location: @device.declared_at,
          hint: "declare dynamic_#{direction}_port(/^\\w+$/, '#{@type}') in its .orogen file, or provide " \
                "#{@bus_model}::#{direction == :output ? 'BusOutSrv' : 'BusInSrv'} in its extension"
        )
      end

      def no_client_port(direction, option)
        verb = direction == :input ? 'receive frames from' : 'send frames to'
        NetworkError.new(
          "#{@device_task.model.name}, the driver of #{@device}, has no #{direction} port of type #{@type} " \
          "to #{verb} #{@bus}",
          location: @device.declared_at,
          hint: "add the port to the driver, or declare the device with #{option}: false if it does not #{verb} the bus"
        )
      end

      def ambiguous_client_ports(direction, option, ports, service_model)
        short = service_model.name.to_s.split('::').last
        port_name = direction == :input ? 'from_bus' : 'to_bus'
        NetworkError.new(
          "#{@device_task.model.name}, the driver of #{@device}, has several #{direction} ports of type " \
          "#{@type}: #{ports.map(&:name).join(', ')}",
          location: @device.declared_at,
          hint: "declare which one in its extension: provides #{service_model}, as: 'bus_client', " \
                "'#{port_name}' => '#{ports.first.name}' (or a #{short.sub(/(In|Out)Srv\z/, 'Srv')} " \
                "for both directions), and pass #{option}: 'bus_client' to device"
        )
      end
    end
  end
end
