# frozen_string_literal: true

require 'helper'

module Syskit
  # Deployment hints (prefer_deployed_tasks) match deployed task names with
  # ===, as in Syskit: names, regexps, and objects such as a Proc; a task's
  # deployment_hints are its requirements', else its devices'.
  class TestDeploymentHintMatching < Minitest::Test
    include SelfTest::ModelsMadeInRuby

    def setup
      super
      @task_m = TaskContext.new_submodel(name: 'HintCamera')
      @robot_config = Config::RobotConfig.new(Syskit.app, 'test')
      @robot_config.use_deployment(@task_m => 'front_cam')
      @robot_config.use_deployment(@task_m => 'rear_cam')
    end

    def deployed_name(requirements)
      result = Network::Generator.new(Syskit.app, [requirements], robot_config: @robot_config)
                                 .generate(through: Network::Generator::STEPS.last)
      result.context.roots.first.name
    end

    def test_a_proc_hint_chooses_the_deployed_tasks_it_accepts
      hint = ->(name) { name.start_with?('rear') }
      assert_equal 'rear_cam', deployed_name(@task_m.prefer_deployed_tasks(hint))
      assert_equal 'front_cam', deployed_name(@task_m.prefer_deployed_tasks(/front/))
      assert_equal 'front_cam', deployed_name(@task_m.prefer_deployed_tasks('front_cam'))
    end

    def test_values_that_never_match_a_name_are_refused
      [3, :rear, nil, true].each do |bad|
        assert_raises(DeclarationError) { @task_m.prefer_deployed_tasks(bad) }
      end
    end

    def test_a_task_takes_the_hints_of_its_requirements_else_of_its_devices
      device_m = Device.new_submodel(name: 'HintDevice')
      driver_m = TaskContext.new_submodel(name: 'HintDriver') { driver_for device_m, as: 'cam' }
      hint = ->(name) { name.include?('cam') }
      device = Robot::RobotDefinition.new.device(device_m, as: 'cam').prefer_deployed_tasks(hint)
      task = driver_m.new(cam_dev: device)
      assert_equal [hint], task.deployment_hints
      task.requirements = driver_m.prefer_deployed_tasks(/own/)
      assert_equal [/own/], task.deployment_hints
    end
  end
end
