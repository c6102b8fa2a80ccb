# frozen_string_literal: true

require_relative 'generator_test_helper'

module Syskit
  # The lookups a driver's configure method and a test call on tasks, as
  # Syskit's data service and bus tests describe them.
  class TestDeviceLookups < Minitest::Test
    include GeneratorTestHelper

    # A driver with two services for one device model: a device chooses
    # one with using: (the other is left for another device).
    DUAL = {
      'models/orogen/dual.orogen' => "name 'dual'\ntask_context 'Task' do\nend\n",
      'models/orogen/dual.rb' => <<~RUBY,
        require 'models/devices/imu'
        Syskit.extend_model OroGen.dual.Task do
          driver_for MyApp::Devices::TemperatureSensor, as: 'front'
          driver_for MyApp::Devices::TemperatureSensor, as: 'rear'
        end
      RUBY
      'config/robots/default.rb' => "using_task_library 'dual'\nusing_task_library 'imu'\n" \
                                    "Syskit.conf.use_deployment OroGen.dual.Task => 'dual'\n" \
                                    "Syskit.conf.use_deployment OroGen.imu.Task => 'imu'\n"
    }.freeze

    def tasks(robot, files = {}, libraries: LIBS)
      generate(robot, files, libraries: libraries).tasks.to_h { |t| [t.name, t] }
    end

    def test_lookups_on_a_task_driving_one_device
      imu = tasks("device(Devices::IMU, as: 'imu')\n")['imu']
      device = MyApp::Profiles::Base.syskit_profile.robot.find_device('imu')
      assert_equal [device], imu.each_master_device.to_a
      assert_same device, imu.find_device_attached_to
      assert_same device, imu.find_device_attached_to('imu')
      assert_same device, imu.find_device_attached_to(MyApp::Devices::IMU)
      assert_same device, imu.find_device_attached_to(OroGen.imu.Task.find_data_service('imu'))
      assert_equal [OroGen.imu.Task.find_data_service('imu')], imu.find_all_driver_services_for(device)
      assert_empty imu.each_com_bus_device.to_a
    end

    def test_lookups_on_a_task_with_two_services_for_its_device
      dual = tasks("device(Devices::TemperatureSensor, as: 'temp', using: OroGen.dual.Task.rear_srv)\n", DUAL,
                   libraries: %w[dual imu])['dual']
      device = MyApp::Profiles::Base.syskit_profile.robot.find_device('temp')
      assert_same OroGen.dual.Task.rear_srv, device.driver_model
      assert_equal [device], dual.each_master_device.to_a
      assert_equal %w[rear], dual.find_all_driver_services_for(device).map(&:name)
      assert_same device, dual.find_device_attached_to('rear')
      assert_nil dual.find_device_attached_to('front')
      error = assert_raises(ConfigurationError) { dual.find_device_attached_to('raer') }
      assert_match(/dual::Task has no service named 'raer' \(did you mean 'rear'\?\)/, error.message)
    end

    def test_a_driver_with_two_services_for_the_device_must_be_given_one
      root = my_app("device(Devices::TemperatureSensor, as: 'temp', using: OroGen.dual.Task)\n",
                    FILES.merge(DUAL), libraries: %w[dual imu])
      errors = load_app(root, problems: true).errors.map(&:message)
      assert_includes errors, "dual::Task has several services that can drive device 'temp' " \
                              '(MyApp::Devices::TemperatureSensor): front, rear'
    end

    def test_lookups_on_a_bus_driver
      tasks = tasks(on_can0)
      bus = MyApp::Profiles::Base.syskit_profile.robot.find_device('can0')
      can0 = tasks['can0']
      assert_equal [bus], can0.each_com_bus_device.to_a
      assert_equal %w[a b], can0.each_attached_device.map(&:name)
      assert_equal %w[a b], can0.each_declared_attached_device.map(&:name)
      assert_empty tasks['a'].each_attached_device.to_a
      device = tasks['a'].robot_device
      assert device.attached_to?(bus)
      assert device.attached_to?('can0')
      refute device.attached_to?('can1')
    end
  end
end
