# frozen_string_literal: true

module Syskit
  module Network
    # Step 1: one driver task per requested device, its +<name>_dev+
    # arguments set to the device.
    class Drivers
      def initialize(context)
        @context = context
        @index = nil
      end

      def run
        @context.requirements.each do |requirement|
          next @context.error(not_a_device(requirement)) unless requirement.is_a?(Requirement)
          next if @context.task_for(requirement.device)

          requirement.device.master_device ? instantiate_slave(requirement) : instantiate(requirement)
        rescue Syskit::Error => e
          @context.error(e)
        end
      end

      # Creates the driver task of +requirement+'s device.
      def instantiate(requirement)
        device = requirement.device
        resolve(device)
        model = device.driver_model
        services = model.driver_services_for(device.model)
        if services.empty?
          raise NetworkError.new("#{model.name} has no driver service for #{device.model}, so #{device} " \
                                 'would leave its task without a device',
                                 location: device.declared_at,
                                 hint: "declare driver_for #{device.model} in #{model.name}'s extension")
        end

        arguments = services.to_h { |srv| [srv.argument_name, device] }
        arguments = requirement.arguments.merge(arguments) unless requirement.arguments.empty?
        task = model.new(arguments)
        task.conf = requirement.conf
        create_slave_ports(task, device)
        @context.add_task(task, device, requirement)
      end

      # A slave device is served by its master's task (see
      # Context#task_for), made here when the master is not in the network
      # yet, with the slave requirement's conf and hints.
      def instantiate_slave(requirement)
        instantiate(Requirement.new(requirement.device.master_device, requirement.profile,
                                    conf: requirement.conf, deployment_hints: requirement.deployment_hints))
      end

      private

      def resolve(device)
        if device.model_resolved? && device.driver_resolved?
          device.resolve_slaves # devices stubbed in tests get their driver directly
        else
          @index ||= Robot::DriverIndex.new(@context.app.orogen, @context.app)
          @index.resolve(device)
        end
      end

      # The ports dynamic services create for the device's slaves (they are
      # the task's from the start, as in Syskit's specialized models).
      def create_slave_ports(task, device)
        device.each_slave do |slave|
          slave.created_ports.each do |port|
            task.create_port(port.direction, port.name, port.type, location: slave.declared_at)
          end
        end
      end

      def not_a_device(requirement)
        what = requirement.respond_to?(:name) ? requirement.name : requirement.inspect
        NetworkError.new(
          "#{what} is not a device: a driver task without a device is refused",
          location: Location.of_caller,
          hint: "pass a profile's device action (Base.gps_dev) or a stub device (syskit_stub_device(Model))"
        )
      end
    end
  end
end
