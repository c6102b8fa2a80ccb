# frozen_string_literal: true

require_relative 'generator_test_helper'

module Syskit
  # A deployment declared on the device (Syskit's deployed_as and
  # deployed_as_unmanaged): the driver runs as the named task, in a
  # deployment of the same name, without a line in the robot configuration.
  class TestDeployedAs < Minitest::Test
    include GeneratorTestHelper

    # The robot configuration deploys two IMU drivers; neither is chosen.
    TWO_IMUS = "using_task_library 'imu'\nSyskit.conf.use_deployment OroGen.imu.Task => 'imu_a'\n" \
               "Syskit.conf.use_deployment OroGen.imu.Task => 'imu_b'\n"

    def test_the_driver_is_deployed_under_the_name
      plan = generate("device(Devices::IMU, as: 'imu').deployed_as('imu_main')\n",
                      'config/robots/default.rb' => TWO_IMUS).plan
      task = plan.tasks.first
      assert_equal %w[imu_main imu_main imu], [task.name, task.deployment, *task.devices]
      refute task.unmanaged
      assert_equal %w[imu_main], plan.order.map(&:task).uniq
    end

    def test_no_robot_configuration_line_is_needed
      plan = generate("device(Devices::IMU, as: 'imu').deployed_as('imu')\n",
                      'config/robots/default.rb' => "# nothing\n").plan
      assert_equal 'imu', plan.find_task('imu').deployment
    end

    def test_an_unmanaged_deployment_is_marked_in_the_plan
      plan = generate("device(Devices::IMU, as: 'imu').deployed_as_unmanaged('imu', on: 'localhost')\n").plan
      assert plan.find_task('imu').unmanaged
      assert_match(/^  imu  imu::Task  \(deployment imu, unmanaged, conf default\)$/, Render::Text.render(plan))
      assert_equal true, plan.to_h['tasks'].first['unmanaged']
    end

    def test_two_devices_deployed_under_one_name
      errors = generation_error(<<~RUBY)
        device(Devices::IMU, as: 'front').deployed_as('imu')
        device(Devices::IMU, as: 'rear')
          .deployed_as('imu')
      RUBY
      assert_reported errors.first, /device 'front' and device 'rear' both need the deployed task imu/,
                      at: 'models/profiles/base.rb:11', hint: /deployed_as\('rear'\)/, root: @root
    end

    def test_a_name_the_robot_configuration_gives_another_device
      errors = generation_error("device(Devices::IMU, as: 'front').prefer_deployed_tasks('imu')\n" \
                                "device(Devices::IMU, as: 'rear').deployed_as('imu')\n")
      assert_reported errors.first, /device 'front' and device 'rear' both need the deployed task imu/,
                      at: 'models/profiles/base.rb:10', root: @root
    end

    def test_an_invalid_name
      root = my_app("device(Devices::IMU, as: 'imu').deployed_as(nil)\n", FILES)
      assert_reported load_problem(root), /invalid deployed task name nil for device 'imu'/,
                      at: 'models/profiles/base.rb:9', hint: /deployed_as\('imu'\)/, root: root
    end

    def test_a_name_on_two_lines
      root = my_app("device(Devices::IMU, as: 'imu').deployed_as(\"imu\\nmain\")\n", FILES)
      assert_reported load_problem(root), /invalid deployed task name "imu\\nmain" for device 'imu'/,
                      at: 'models/profiles/base.rb:9', root: root
    end

    # Orocos takes any text on a line: Rock's tests name tasks after the
    # process and the test ("4242-test_0001_reads the depth").
    def test_a_name_is_any_text_on_one_line
      plan = generate("device(Devices::IMU, as: 'imu').deployed_as('4242-test_0001_reads the depth')\n").plan
      assert_equal '4242-test_0001_reads the depth', plan.find_task('4242-test_0001_reads the depth').deployment
    end
  end
end
