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

          instantiate(requirement)
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

        task = model.new(services.to_h { |srv| [srv.argument_name, device] })
        task.conf = requirement.conf
        @context.add_task(task, device, requirement)
      end

      private

      def resolve(device)
        return if device.model_resolved? && device.driver_resolved?

        @index ||= Robot::DriverIndex.new(@context.app.orogen, @context.app)
        @index.resolve(device)
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
