# frozen_string_literal: true

module Syskit
  module Network
    # The driver tasks of devices: one per device, its +<name>_dev+
    # arguments set to the device (see Instantiate, which asks for them).
    class Drivers
      def initialize(context)
        @context = context
        @index = nil
      end

      # The driver task of +requirement+'s device (a slave device's is its
      # master's), made now. +expected_model+: the task model the device's
      # driver must be (a composition child naming the driver).
      def instantiate_device(requirement, expected_model: nil)
        device = requirement.device
        return instantiate_slave(requirement) if device.master_device

        task = instantiate(requirement)
        check_expected(task, device, expected_model, requirement) if expected_model
        task
      end

      # Creates the driver task of +requirement+'s device.
      def instantiate(requirement)
        device = requirement.device
        resolve(device)
        model = device.driver_model.component_model
        services = model.driver_services_for(device.model)
        if services.empty?
          raise NetworkError.new("#{model.name} has no driver service for #{device.model}, so #{device} " \
                                 'would leave its task without a device',
                                 location: device.declared_at,
                                 hint: "declare driver_for #{device.model} in #{model.name}'s extension")
        end

        arguments = device.driver_arguments
        given = requirement.arguments
        # A device's own requirements give the same (frozen) driver arguments.
        arguments = given.merge(arguments) unless given.empty? || given.equal?(arguments)
        task = model.new(arguments)
        Instantiate.assign_conf(task, requirement)
        create_slave_ports(task, device)
        @context.add_task(task, device, requirement)
      end

      # A slave device is served by its master's task (see
      # Context#task_for), made here when the master is not in the network
      # yet, with the slave requirement's conf and hints.
      def instantiate_slave(requirement)
        master = requirement.device.master_device
        @context.task_for(master) ||
          instantiate(InstanceRequirements.new(device: master, profile: requirement.profile,
                                               conf: requirement.conf, deployment_hints: requirement.deployment_hints,
                                               declared_at: requirement.declared_at))
      end

      def check_expected(task, device, model, requirement)
        return if task.model <= model

        raise NetworkError.new(
          "#{device} is driven by #{task.model.name}, but it is selected where a #{model.name} is required",
          location: requirement.declared_at || device.declared_at,
          hint: "select a device driven by #{model.name}, or declare the device with using: #{model.name}"
        )
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
    end
  end
end
