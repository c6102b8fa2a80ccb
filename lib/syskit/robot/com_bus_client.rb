# frozen_string_literal: true

module Syskit
  module Robot
    # The services of an attached device's driver that link it to its bus
    # (Syskit's +combus_client_in_srv+ and +combus_client_out_srv+): the
    # ClientInSrv the bus's frames come in through, the ClientOutSrv the
    # device's go out through. The device's +bus_to_client:+ and
    # +client_to_bus:+ options name the service when there are several, or
    # are false for a direction the device does not use. Part of
    # MasterDeviceInstance; the network generator links the ports through
    # the same choice (Network::BusPorts).
    module ComBusClient
      # The driver's service the bus's frames come in through, seen as
      # the bus model's ClientInSrv; nil for a device the bus does not
      # write to, or a driver that reads them on a plain port.
      def combus_client_in_srv
        combus_client_srv(:bus_to_client)
      end

      # The driver's service the device's frames go out through, seen as
      # the bus model's ClientOutSrv.
      def combus_client_out_srv
        combus_client_srv(:client_to_bus)
      end

      # The service of +driver+ providing +srv_m+ that links the device to
      # +bus+, seen as +srv_m+: the one named +name+, else the only one;
      # nil when it has none. +option+ is the device option that names it.
      def resolve_combus_client_srv(srv_m, name, bus, option, driver = driver_model.component_model,
                                    location: declared_at)
        combus_client_service(driver, srv_m, name, bus, option, location: location)&.as(srv_m)
      end

      # The service itself (see #resolve_combus_client_srv).
      # Errors are located at +location+ (the device's declaration, or
      # the attach_to call).
      def combus_client_service(driver, srv_m, name, bus, option, location: declared_at)
        services = driver.services_fulfilling(srv_m)
        if name
          services.find { |srv| srv.name == name } ||
            raise(unknown_client_service(driver, srv_m, name, services, [bus, option, location]))
        elsif services.size > 1
          raise ambiguous_client_services(driver, services, [bus, option, location])
        else
          services.first
        end
      end

      # Checks, once its driver is known, that the device can talk to its
      # bus in the directions it uses: through a client service, or through
      # the driver's single port of the bus's message type.
      def check_combus_attachment(location = declared_at)
        # A bus on a bus is linked by its driver's own bus ports.
        return unless attached? && driver_resolved? && !com_bus?

        COMBUS_DIRECTIONS.each do |option, (direction, srv_name)|
          next unless public_send(:"#{option}?")
          next if combus_client_srv(option, location)
          next if driver_model.component_model.static_ports_of(direction, bus.model.message_type).size == 1

          raise no_client_io(option, direction, srv_name, location)
        end
      end

      # Each option, the direction of the driver's port it stands for and
      # the client service of that direction.
      COMBUS_DIRECTIONS = { bus_to_client: [:input, 'client_in_srv'],
                            client_to_bus: [:output, 'client_out_srv'] }.freeze

      private

      def combus_client_srv(option, location = declared_at)
        return unless attached? && public_send(:"#{option}?") && driver_resolved?

        wanted = public_send(option)
        srv_m = bus.model.public_send(COMBUS_DIRECTIONS[option].last)
        resolve_combus_client_srv(srv_m, wanted.is_a?(String) ? wanted : nil, bus, option.to_s, location: location)
      end

      def unknown_client_service(driver, srv_m, name, services, (bus, option, location))
        hint = if services.empty?
                 "provide it: provides #{srv_m}, as: '#{name}'"
               else
                 "its services of that kind: #{services.map(&:name).join(', ')}"
               end
        DeclarationError.new(
          "#{option}: '#{name}' names no #{srv_m} service of #{driver.name}, to link #{self} to #{bus}" \
          "#{Naming.did_you_mean(name, services.map(&:name))}",
          location: location, hint: hint
        )
      end

      def ambiguous_client_services(driver, services, (bus, option, location))
        DeclarationError.new(
          "#{driver.name}, the driver of #{self}, provides several bus client services to link it to #{bus}: " \
          "#{services.map(&:name).join(', ')}",
          location: location, hint: "choose one with #{option}: '#{services.first.name}' in the device declaration"
        )
      end

      def no_client_io(option, direction, srv_name, location)
        srv_m = bus.model.public_send(srv_name)
        DeclarationError.new(
          "#{driver_model.component_model.name}, the driver of #{self}, has no #{srv_m} service " \
          "and no single #{direction} port " \
          "of type #{bus.model.message_type} to link it to #{bus}",
          location: location,
          hint: "provide #{srv_m} in its extension, or attach the device with #{option}: false"
        )
      end
    end
  end
end
