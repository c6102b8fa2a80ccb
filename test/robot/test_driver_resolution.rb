# frozen_string_literal: true

require 'helper'

module Syskit
  # Which component drives each device: using:, the single driver loaded, or
  # errors that say what to load or choose (SPEC 5 and 11).
  class TestDriverResolution < Minitest::Test
    SECOND_IMU_DRIVER = {
      'models/orogen/imu2.orogen' => <<~RUBY,
        name 'imu2'
        import_types_from 'base'
        task_context 'Task' do
          output_port 'samples', '/base/samples/IMUSensors'
        end
      RUBY
      'models/orogen/imu2.rb' => <<~RUBY
        require 'models/devices/imu'
        Syskit.extend_model(OroGen.imu2.Task) { driver_for MyApp::Devices::IMU, as: 'imu' }
      RUBY
    }.freeze

    def test_the_single_loaded_driver_is_used
      load_app(my_app("device(Devices::IMU, as: 'imu')\n"))
      assert_same OroGen.imu.Task, MyApp::Profiles::Base.imu_dev.device.driver_model.component_model
    end

    def test_no_driver_names_the_library_to_load
      root = my_app("device(Devices::IMU, as: 'imu')\n", libraries: %w[temp])
      error = load_problem(root, robots: [])
      assert_reported error, Regexp.new('no driver is known for device \'imu\' \(MyApp::Devices::IMU\): ' \
                                        'task library imu has one but is not loaded \(loaded task libraries: temp\)'),
                      at: 'models/profiles/base.rb:7',
                      hint: /add using_task_library 'imu' \(its extension file declares a driver for IMU\)/,
                      root: root
    end

    def test_no_driver_for_a_bus_of_the_app_named_like_a_bundled_one
      bus = "module MyApp\n  module Devices\n    module Bus\n      " \
            "com_bus_type 'CAN', message_type: '/canbus/Message'\n    end\n  end\nend\n"
      root = my_app("com_bus(Devices::Bus::CAN, as: 'can0')\n", { 'models/devices/bus/can.rb' => bus },
                    libraries: [])
      error = load_problem(root, robots: [])
      assert_reported error, /no driver is known for bus 'can0' \(MyApp::Devices::Bus::CAN\): none is loaded/,
                      at: 'models/profiles/base.rb:7', hint: /declare driver_for MyApp::Devices::Bus::CAN/, root: root
    end

    def test_no_driver_anywhere
      root = my_app("device(Devices::TemperatureSensor, as: 't')\n", { 'models/orogen/temp.rb' => "# no driver\n" })
      error = load_problem(root)
      assert_reported error, /no driver is known for device 't'/,
                      at: 'models/profiles/base.rb:9', hint: /declare driver_for MyApp::Devices::TemperatureSensor/,
                      root: root
    end

    def test_several_drivers_need_using
      root = my_app("device(Devices::IMU, as: 'imu')\n", SECOND_IMU_DRIVER, libraries: %w[imu imu2])
      error = load_problem(root)
      assert_reported error, /several drivers can drive device 'imu' \(MyApp::Devices::IMU\): imu2::Task, imu::Task/,
                      at: 'models/profiles/base.rb:8',
                      hint: /using: option, e.g. device\(MyApp::Devices::IMU, as: 'imu', using: OroGen.imu2.Task\)/,
                      root: root
    end

    def test_using_chooses_one_of_several_drivers
      load_app(my_app("device(Devices::IMU, as: 'imu', using: OroGen.imu2.Task)\n", SECOND_IMU_DRIVER,
                      libraries: %w[imu imu2]))
      assert_same OroGen.imu2.Task, MyApp::Profiles::Base.imu_dev.device.driver_model.component_model
    end

    def test_using_a_task_that_does_not_drive_the_device
      root = my_app("device(Devices::IMU, as: 'imu', using: OroGen.temp.Task)\n")
      error = load_problem(root)
      assert_reported error, /temp::Task does not drive MyApp::Devices::IMU \(device 'imu'\)/,
                      at: 'models/profiles/base.rb:9', hint: /drivers of MyApp::Devices::IMU: imu::Task/, root: root
    end

    def test_using_something_that_is_not_a_task_model
      root = my_app("device(Devices::IMU, as: 'imu', using: 'imu::Task')\n")
      assert_reported load_problem(root), /using: expects a driver task model, got "imu::Task"/,
                      at: 'models/profiles/base.rb:9', hint: /using: OroGen.library.Task/, root: root
    end

    def test_a_driver_task_model_in_place_of_the_device_model
      load_app(my_app("device(OroGen.imu.Task, as: 'imu')\n"))
      device = MyApp::Profiles::Base.imu_dev.device
      assert_same MyApp::Devices::IMU, device.model
      assert_same OroGen.imu.Task, device.driver_model.component_model
    end

    def test_a_task_model_that_drives_no_device
      root = my_app("device(OroGen.imu.Task, as: 'imu')\n", { 'models/orogen/imu.rb' => "# nothing\n" })
      assert_reported load_problem(root), /imu::Task drives no device/,
                      at: 'models/profiles/base.rb:9',
                      hint: /declare driver_for DeviceModel, as: 'name' in the extension file of imu::Task/, root: root
    end

    def test_a_bus_driver_task_model_is_not_a_device
      root = my_app("device(OroGen.canbus.Task, as: 'x')\n")
      assert_reported load_problem(root), /canbus::Task drives no device/,
                      at: 'models/profiles/base.rb:9', hint: /declare driver_for DeviceModel/, root: root
    end

    def test_load_order_does_not_matter
      # The profile is loaded before the file that loads the driver library.
      root = my_app("device(Devices::IMU, as: 'imu')\n",
                    { 'models/profiles/zz_drivers.rb' => "using_task_library 'imu'\n" }, libraries: [])
      load_app(root)
      assert_same OroGen.imu.Task, MyApp::Profiles::Base.imu_dev.device.driver_model.component_model
    end

    def test_abstract_task_models_are_not_candidates
      files = {
        'models/orogen/imu.orogen' => <<~RUBY,
          name 'imu'
          import_types_from 'base'
          task_context 'Base' do
            abstract
            output_port 'samples', '/base/samples/IMUSensors'
          end
          task_context 'Task', subclasses: 'Base' do
          end
        RUBY
        'models/orogen/imu.rb' => <<~RUBY
          require 'models/devices/imu'
          Syskit.extend_model(OroGen.imu.Base) { driver_for MyApp::Devices::IMU, as: 'imu' }
        RUBY
      }
      load_app(my_app("device(Devices::IMU, as: 'imu')\n", files))
      assert_same OroGen.imu.Task, MyApp::Profiles::Base.imu_dev.device.driver_model.component_model
      assert OroGen.imu.Task.method_defined?(:imu_dev)
    end
  end
end
