# frozen_string_literal: true

require 'helper'

module Syskit
  # data_service_type, device_type, com_bus_type, provides, driver_for:
  # what they define and the errors they report (SPEC 3 and 4).
  class TestModelDeclarations < Minitest::Test
    def models_app(source, path: 'models/devices/things.rb', extra: {})
      root = my_app(nil, { path => source }.merge(extra))
      [root, load_app(root, problems: true)]
    end

    def problem_in(source, **options)
      root, app = models_app(source, **options)
      assert_equal 1, app.problems.size, app.problems.map { |e| e.report(root) }.join("\n")
      [app.problems.first, root]
    end

    def test_models_are_constants_of_the_enclosing_module_with_their_ports
      _, app = models_app(<<~RUBY)
        module MyApp
          module Services
            data_service_type 'Pose' do
              output_port 'pose', '/base/samples/RigidBodyState'
            end
          end
          module Devices
            device_type 'Odometer' do
              output_port 'odometry', '/base/samples/RigidBodyState'
              provides Services::Pose, 'pose' => 'odometry'
              input_port 'reset', '/bool'
            end
          end
        end
      RUBY
      assert_empty app.problems
      odometer = MyApp::Devices::Odometer
      assert_equal 'MyApp::Devices::Odometer', odometer.name
      assert odometer.fullfills?(MyApp::Services::Pose)
      assert odometer.fullfills?(Syskit::Device)
      assert_equal({ 'odometry' => :output, 'reset' => :input }, odometer.ports.transform_values(&:direction))
      assert_equal({ 'pose' => 'odometry' }, odometer.port_mappings_for(MyApp::Services::Pose))
    end

    def test_a_device_can_provide_another_device
      _, app = models_app(<<~RUBY)
        module MyApp
          module Devices
            device_type 'Camera'
            device_type 'StereoCamera' do
              provides Camera
            end
          end
        end
      RUBY
      assert_empty app.problems
      assert MyApp::Devices::StereoCamera.fullfills?(MyApp::Devices::Camera)
    end

    def test_a_name_that_is_not_a_constant_name
      error, root = problem_in("module MyApp\n  device_type 'gps_f9'\nend\n")
      assert_reported error, /'gps_f9' is not a valid name for a device/, at: 'models/devices/things.rb:2',
                                                                          hint: /GpsF9/, root: root
    end

    def test_a_model_declared_twice_is_reopened_with_a_warning
      source = "module MyApp\n  device_type 'Gyro'\n  device_type('Gyro') { output_port 'r', 'int' }\nend"
      error, root = problem_in(source)
      assert_reported error, %r{MyApp::Gyro is declared again \(first at models/devices/things.rb:2\)},
                      at: 'models/devices/things.rb:3', hint: /remove one/, root: root
      assert_kind_of Warning, error
      assert MyApp::Gyro.ports.key?('r'), 'the second declaration adds to the first'
    end

    def test_a_name_declared_as_another_kind_of_model
      error, root = problem_in("module MyApp\n  device_type 'Gyro'\n  data_service_type 'Gyro'\nend\n")
      assert_reported error, %r{MyApp::Gyro is already defined at models/devices/things.rb:2},
                      at: 'models/devices/things.rb:3', hint: /another name/, root: root
    end

    def test_a_data_service_cannot_provide_a_device
      error, root = problem_in("module MyApp\n  data_service_type 'Pose' do\n    provides Devices::IMU\n  end\nend\n")
      assert_reported error, /MyApp::Pose is a data service and cannot provide the device MyApp::Devices::IMU/,
                      at: 'models/devices/things.rb:3', hint: /declare it with device_type/, root: root
    end

    def test_a_device_cannot_provide_a_bus
      error, root = problem_in(<<~RUBY)
        module MyApp
          device_type 'Gateway' do
            provides CommonModels::Devices::Bus::CAN
          end
        end
      RUBY
      assert_reported error, /MyApp::Gateway is a device and cannot provide the communication bus/,
                      at: 'models/devices/things.rb:3', hint: /com_bus_type/, root: root
    end

    def test_provides_something_that_is_not_a_model
      error, root = problem_in("module MyApp\n  device_type 'Gyro' do\n    provides 'Pose'\n  end\nend\n")
      assert_reported error, /provides expects a data service, device or bus model, got "Pose"/,
                      at: 'models/devices/things.rb:3', root: root
    end

    def test_port_collision_in_provides
      source = <<~RUBY
        module MyApp
          data_service_type('Pose') { output_port 'samples', '/base/samples/RigidBodyState' }
          device_type 'Gyro' do
            output_port 'samples', '/double'
            provides Pose
          end
        end
      RUBY
      error, root = problem_in(source)
      assert_reported error, Regexp.new('MyApp::Pose\'s output port \'samples\' \(/base/samples/RigidBodyState\) ' \
                                        'collides with MyApp::Gyro\'s output port \'samples\' \(/double\)'),
                      at: 'models/devices/things.rb:5', hint: /provides MyApp::Pose, 'samples' => 'other_name'/,
                      root: root
    end

    def test_mapping_to_an_unknown_port
      source = <<~RUBY
        module MyApp
          data_service_type('Pose') { output_port 'samples', '/double' }
          device_type 'Gyro' do
            provides Pose, 'sample' => 'rate'
          end
        end
      RUBY
      error, root = problem_in(source)
      assert_reported error, /MyApp::Pose has no port named 'sample' or 'rate'/,
                      at: 'models/devices/things.rb:4', hint: /write 'samples' => 'your_port'/, root: root
    end

    def test_unknown_port_type
      error, root = problem_in(<<~RUBY)
        module MyApp
          data_service_type 'Pose' do
            output_port 'p', '/my/Pos'
          end
        end
      RUBY
      assert_reported error, %r{unknown type /my/Pos}, at: 'models/devices/things.rb:3', hint: /import_types_from/,
                                                       root: root
    end

    def test_bus_model_needs_a_message_type
      error, root = problem_in("module MyApp\n  com_bus_type 'Serial'\nend\n")
      assert_reported error, /MyApp::Serial has no message type/,
                      at: 'models/devices/things.rb:2',
                      hint: %r{com_bus_type 'Serial', message_type: '/canbus/Message'}, root: root
    end

    def test_bus_model_inherits_the_message_type_and_device_configuration_of_the_bus_it_provides
      _, app = models_app(<<~RUBY)
        module MyApp
          com_bus_type 'J1939' do
            provides CommonModels::Devices::Bus::CAN
          end
        end
      RUBY
      assert_empty app.problems
      j1939 = MyApp::J1939
      assert_same ::Types.canbus.Message, j1939.message_type
      assert j1939::BusSrv.fullfills?(CommonModels::Devices::Bus::CAN::BusSrv)
      assert_equal CommonModels::Devices::Bus::CAN.attached_device_configuration_modules,
                   j1939.attached_device_configuration_modules
    end

    def test_bus_model_cannot_provide_a_bus_of_another_message_type
      source = <<~RUBY
        module MyApp
          com_bus_type 'Serial', message_type: '/std/string' do
            provides CommonModels::Devices::Bus::CAN
          end
        end
      RUBY
      error, root = problem_in(source)
      assert_reported error, Regexp.new('MyApp::Serial \(message type /std/string\) cannot provide ' \
                                        'CommonModels::Devices::Bus::CAN \(message type /canbus/Message\)'),
                      at: 'models/devices/things.rb:3', hint: /same message type/, root: root
    end

    def test_extend_device_configuration_adds_methods_to_devices_of_the_model
      source = <<~RUBY
        module MyApp
          device_type 'Lidar' do
            extend_device_configuration do
              dsl_attribute :range
              def describe
                "lidar up to \#{range}m"
              end
            end
          end
        end
      RUBY
      root = my_app("device(Lidar, as: 'lidar').range(30)\n", { 'models/devices/things.rb' => source })
      root = root.sub('base.rb', 'base.rb')
      File.write(File.join(root, 'models/orogen/lidar.orogen'), "name 'lidar'\ntask_context 'Task' do\nend\n")
      File.write(File.join(root, 'models/orogen/lidar.rb'),
                 "Syskit.extend_model(OroGen.lidar.Task) { driver_for MyApp::Lidar, as: 'lidar' }\n")
      profile = File.join(root, 'models/profiles/base.rb')
      File.write(profile, File.read(profile).sub("using_task_library 'imu'", "using_task_library 'lidar'"))
      load_app(root)
      device = MyApp::Profiles::Base.lidar_dev.device
      assert_equal 30, device.range
      assert_equal 'lidar up to 30m', device.describe
    end

    def test_timing_statements_are_accepted_and_recorded
      _, app = models_app(<<~RUBY)
        module MyApp
          device_type 'Gyro' do
            worstcase_processing_time 0.2
            output_port('rate', '/double').period(0.01)
          end
        end
      RUBY
      assert_empty app.problems
      assert_equal 0.2, MyApp::Gyro.worstcase_processing_time
      assert_equal 0.01, MyApp::Gyro.find_port('rate').period
    end

    def test_a_custom_device_model_class_gives_its_api_to_its_models
      source = <<~RUBY
        module MyApp
          class SensorModel < Syskit::Models::DeviceModel
            def range(value = nil)
              value ? @range = value : @range
            end
          end
          Sensor = SensorModel.new
          Sensor.provides Syskit::Device
          device_type 'Sonar', parent: Sensor do
            range 50
          end
        end
      RUBY
      _, app = models_app(source)
      assert_empty app.problems
      assert_instance_of MyApp::SensorModel, MyApp::Sonar
      assert_equal 50, MyApp::Sonar.range
      assert MyApp::Sonar.fullfills?(MyApp::Sensor)
      assert_equal 'MyApp::Sensor', MyApp::Sensor.name
    end

    def test_parent_must_be_a_device_model
      error, root = problem_in("module MyApp\n  device_type 'Sonar', parent: String\nend\n")
      assert_reported error, /parent: expects a device model, got String/, at: 'models/devices/things.rb:2', root: root
    end
  end
end
