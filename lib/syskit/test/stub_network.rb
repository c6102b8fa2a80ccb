# frozen_string_literal: true

module Syskit
  module Test
    # Syskit's network stubbing on tasks already in the test's plan
    # (+Cmp.instanciate(plan)+): each abstract task is replaced by a task
    # of a stub model providing the same services (see StubModels), in
    # the plan and in the compositions it is a child of. Plan services
    # (+task.as_service+) follow the replacements.
    #
    #   stubs = StubNetwork.new(self)
    #   cmp = stubs.apply([Cmp.instanciate(plan)]).first
    #   cmp.srv_child.abstract? # => false
    class StubNetwork
      # +test+ gives the plan (+test.plan+).
      def initialize(test)
        @plan = test.plan
      end

      # Stubs the networks of +root_tasks+ and returns, for each root, the
      # task that stands for it afterwards (itself unless it was abstract).
      def apply(root_tasks)
        replacements = {}.compare_by_identity
        root_tasks.map { |task| stub(task, replacements) }
      end

      private

      def stub(task, replacements)
        return replacements[task] if replacements.key?(task)

        replacement = task.abstract? ? concrete_task(task) : task
        stub_devices(replacement)
        replacements[task] = replacement
        @plan.replace_task(task, replacement) unless replacement.equal?(task)
        if replacement.is_a?(Composition)
          replacement.children_by_role.to_a.each do |role, child|
            stubbed = stub(child, replacements)
            replacement.add_child(role, stubbed) unless stubbed.equal?(child)
          end
        end
        replacement
      end

      # A task of a stub model standing for abstract +task+: the driver of
      # a stub device for a device model.
      def concrete_task(task)
        model = task.model
        device_model = model.placeholder? && model.proxied_data_service_models.grep(Models::DeviceModel).first
        return stub_devices(Network::StubModels.device_driver(device_model).new(task.arguments.to_h)) if device_model

        stub_model =
          if model.placeholder?
            base = model.proxied_component_model
            base = nil if base.equal?(Syskit::Component) || base.equal?(Syskit::TaskContext)
            Network::StubModels.service_provider(model.proxied_data_service_models, base: base)
          else
            Network::StubModels.service_provider([], base: model)
          end
        stub_model.new(task.arguments.to_h)
      end

      # Gives a driver task a stub device of each model it drives that no
      # argument gives it yet; returns the task.
      def stub_devices(task)
        task.model.driver_services.each do |srv|
          name = srv.argument_name
          next if task.arguments.set?(name)

          task.arguments[name] = stub_device(srv.driven_device_model, task.model)
        end
        task
      end

      def stub_device(device_model, driver)
        robot = (@robot ||= Robot::Definition.new(nil))
        device = robot.add_device(Robot::MasterDeviceInstance, device_model,
                                  "stub#{robot.each_master_device.count}", using: driver, options: {}, location: nil)
        device.driver_model = driver
        device
      end
    end
  end
end
