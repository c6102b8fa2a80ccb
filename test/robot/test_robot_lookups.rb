# frozen_string_literal: true

require 'helper'

module Syskit
  # Looking up a robot's devices under Syskit's names, and the timing
  # settings Syskit accepts (burst(0) is its default).
  class TestRobotLookups < Minitest::Test
    FILES = {
      'models/devices/camera.rb' => <<~RUBY,
        module MyApp
          module Devices
            device_type('Camera') { output_port 'image', '/double' }
            device_type 'Stereo'
          end
        end
      RUBY
      'models/orogen/stereo.orogen' => <<~RUBY,
        name 'stereo'
        task_context 'Task' do
          output_port 'left_image', '/double'
        end
      RUBY
      'models/orogen/stereo.rb' => <<~RUBY
        require 'models/devices/camera'
        Syskit.extend_model OroGen.stereo.Task do
          driver_for MyApp::Devices::Stereo, as: 'stereo'
          driver_for MyApp::Devices::Camera, as: 'left', slave_of: 'stereo', 'image' => 'left_image'
        end
      RUBY
    }.freeze

    ROBOT = <<~RUBY
      device(MyApp::Devices::IMU, as: 'imu').burst(0)
      device(MyApp::Devices::Stereo, as: 'cam')
    RUBY

    def robot
      root = my_app(ROBOT, FILES, libraries: %w[imu stereo])
      load_app(root)
      MyApp::Profiles::Base.syskit_profile.robot
    end

    def test_devices_by_name
      robot = self.robot
      assert robot.has_device?('imu')
      assert robot.has_device?('cam.left')
      refute robot.has_device?('cam.right')
      refute robot.empty?
      assert Robot::RobotDefinition.new.empty?
    end

    def test_devices_enumerated
      robot = self.robot
      assert_equal %w[imu cam], robot.each_master_device.map(&:name)
      assert_equal %w[imu cam cam.left], robot.each_device.map(&:full_name)
    end

    def test_burst_zero_is_accepted_and_a_negative_burst_is_not
      assert_equal 0, robot.find_device('imu').burst
      @loaded_apps.pop.unload
      root = my_app("device(MyApp::Devices::IMU, as: 'imu').burst(-1)")
      assert_reported load_problem(root), /invalid burst -1 for/, at: 'models/profiles/base.rb:9',
                                                                  hint: /an integer, 0 or more/, root: root
    end
  end
end
