# frozen_string_literal: true

module Syskit
  module Test
    # Network generation in Syskit's own tests (syskit/test/self), with the
    # deployments the test declares: +use_deployment Task => 'name'+ (as a
    # robot configuration's), deployment models made by
    # +syskit_stub_deployment_model+, and the requirements' own
    # (+Task.deployed_as('name')+). See Stubs#syskit_stub_and_deploy for
    # generation with stubbed deployments.
    module NetworkManipulation
      # A deployment model running one task of +task_model+ named +name+
      # (by default the name oroGen gives a task model's default
      # deployment); the block declares more tasks (+task 'n', Model+).
      def syskit_stub_deployment_model(task_model = nil, name = nil, &block)
        name ||= "orogen_default_#{task_model&.name.to_s.gsub(/\W+/, '__')}"
        Syskit::Deployment.new_submodel(name: name) do
          task(name, task_model) if task_model
          instance_eval(&block) if block
        end
      end

      # A configured deployment (Models::ConfiguredDeployment) of one task
      # of +task_model+ named +task_name+, on the process server +on+;
      # with +register:+ (the default) the test deploys with it.
      # Syskit's +remote_task:+ (whether the process would be a remote
      # one) is accepted: nothing runs.
      def syskit_stub_configured_deployment(task_model = nil, task_name = nil, process_server_name: 'stubs',
                                            register: true, remote_task: false, &block) # rubocop:disable Lint/UnusedMethodArgument
        model = syskit_stub_deployment_model(task_model, task_name, &block)
        configured = Models::ConfiguredDeployment.new(process_server_name, model)
        use_deployment(configured) if register
        configured
      end

      # Deploys, in this test, task instances as a robot configuration
      # does (see Config::RobotConfig#use_deployment): a task model by
      # name (+Task => 'name'+), or a deployment model.
      def use_deployment(*specs, **options)
        syskit_test_robot_config.use_deployment(*specs, **options)
      end

      # The robot configuration of the test: what it deployed with
      # #use_deployment. As in Syskit's harness, it has the process server
      # 'stubs' (on this machine), where stub deployments run.
      def syskit_test_robot_config
        @syskit_test_robot_config ||= Config::RobotConfig.new(Test.app, 'test').tap do |config|
          config.register_process_server('stubs', nil, host_id: 'localhost')
        end
      end

      # Syskit's +default_deployment_group+: the deployments of the test
      # (a robot configuration is a Models::DeploymentGroup).
      def default_deployment_group
        syskit_test_robot_config
      end

      # Generates and deploys the network of +requirements+ (models,
      # requirements, or what answers +to_action+) with the test's
      # deployments and the requirements' own; returns the task of each
      # (one task when given one).
      def syskit_deploy(*requirements)
        syskit_generate(requirements, Network::Generator::STEPS.last)
      end

      # Generates the network of +requirements+ without deploying it (no
      # deployment needed); returns the task of each.
      def syskit_generate_network(*requirements)
        syskit_generate(requirements, Network::Merge)
      end

      private

      def syskit_generate(requirements, through)
        requirements = requirements.flatten
        resolved = requirements.map { |r| Test.requirements_of(r) }
        result = Network::Generator.new(Test.app, resolved, robot_config: syskit_test_robot_config)
                                   .generate(through: through)
        roots = result.context.roots
        requirements.size == 1 ? roots.first : roots
      end
    end
  end
end
