# frozen_string_literal: true

module Syskit
  module Test
    # Assertions on the task model a test describes, as Syskit's generated
    # driver tests write them:
    #
    #   module OroGen
    #     describe canbus.Task do
    #       it { is_configurable }
    #     end
    #   end
    module TaskAssertions
      # The task model (the described one by default) can be configured:
      # each device or bus it drives is stubbed and its task stub-deployed
      # and configured, as syskit_stub_deploy_and_configure does; a model
      # that drives nothing is configured on its own (its 'default' section,
      # its configure method and its stubs).
      def is_configurable(model = syskit_described_task_model) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        syskit_stub_deploy_and_configure(model)
        assert true
      rescue Syskit::Error => e
        flunk e.report(Test.app.root)
      end
      alias assert_is_configurable is_configurable

      private

      # The subject model (see SubjectModel), when it is a task model or
      # requirements of one.
      def syskit_described_task_model
        model = subject_syskit_model
        task_model = model.respond_to?(:component_model) ? model.component_model : model
        return model if task_model.is_a?(Class) && task_model < TaskContext

        flunk "is_configurable needs a task model (describe OroGen.library.Task do ... end), not #{model.inspect}"
      rescue ArgumentError => e
        flunk "is_configurable: #{e.message}"
      end

      # Stub devices for the services through which +model+ drives devices
      # and buses (one each), or none when it drives nothing.
      def syskit_stub_driven_devices(model)
        model.driver_services.map do |srv|
          driven = srv.driven_device_model
          if driven.is_a?(Models::ComBusModel)
            syskit_stub_com_bus(driven, driver: model)
          else
            syskit_stub_device(driven, driver: model)
          end
        end
      end

      # A task model, or its requirements (+with_conf+, +with_arguments+):
      # its devices stubbed, deployed and configured.
      def syskit_stub_requirements_and_configure(requirements)
        devices = syskit_stub_driven_devices(requirements.component_model)
        return syskit_configure_alone(requirements) if devices.empty?

        devices.map do |dev|
          requirement = InstanceRequirements.new(device: dev, conf: requirements.conf_given? ? requirements.conf : nil,
                                                 arguments: requirements.arguments)
          syskit_stub_deploy_and_configure(requirement)
        end.first
      end

      # Configures a task of +requirements+' model made for no device.
      def syskit_configure_alone(requirements)
        model = requirements.component_model
        context = Network::Context.new(app: Test.app, requirements: [], stub_deployments: true)
        task = model.new(requirements.arguments.dup)
        Network::Instantiate.assign_conf(task, requirements)
        deployment = Orogen::DeploymentSpec.new("stub_#{model.name.tr(':', '_')}")
        task.deployed_task = deployment.add_task("stub_#{model.name.split('::').last.downcase}", model)
        Network::Configure.new(context).configure(task)
        context.raise_errors
        @task = task
      end
    end
  end
end
