# frozen_string_literal: true

require 'helper'

module Syskit
  # What extend_device_configuration blocks may define, and how device
  # attributes read in a robot block.
  class TestDeviceConfiguration < Minitest::Test
    def problem_in(source)
      root = my_app(nil, { 'models/devices/things.rb' => source })
      app = load_app(root, problems: true)
      assert_equal 1, app.problems.size, app.problems.map { |e| e.report(root) }.join("\n")
      [app.problems.first, root]
    end

    # Methods every device has (name, with_conf, raise...) cannot be
    # replaced by a configuration module, whether by dsl_attribute or def.
    def test_configuration_methods_cannot_replace_the_methods_of_devices
      { 'dsl_attribute :name' => 'name', "def with_conf(*)\n  self\nend" => 'with_conf',
        "def raise(*)\nend" => 'raise' }.each do |statement, method|
        error, root = problem_in(<<~RUBY)
          module MyApp
            device_type 'Lidar' do
              extend_device_configuration do
                dsl_attribute :range
                #{statement.gsub("\n", "\n        ")}
              end
            end
          end
        RUBY
        assert_reported error, /'#{method}' is a method of every device/, at: 'models/devices/things.rb:5', root: root
        Syskit.app.unload # the next statement is tried in a new app
      end
    end

    # In a robot block, an attribute read without arguments is a setting
    # whose arguments were forgotten; once the robot is declared (in
    # configure methods, in tests), reading an unset attribute gives nil.
    def test_unset_attributes_read_nil_once_the_robot_is_declared
      root = my_app(<<~RUBY)
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through 'can0' do
          device(Devices::TemperatureSensor, as: 'sensor')
        end
      RUBY
      device = load_app(root).profiles.values.first.robot.find_device('sensor')
      assert_nil device.can_id
      assert_nil device.period
    end

    def test_reading_an_unset_attribute_in_the_robot_block_is_an_error
      root = my_app("device(Devices::IMU, as: 'imu').period.with_conf('default')\n")
      error = load_problem(root)
      assert_reported error, /period without arguments reads the period of device 'imu', which is not set/,
                      at: 'models/profiles/base.rb:9', hint: /a positive number of seconds: .period/, root: root
    end
  end
end
