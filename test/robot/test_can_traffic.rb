# frozen_string_literal: true

require 'helper'

module Syskit
  # The CAN traffic statements: .bitrate on CAN buses, .frame on the
  # devices attached to them.
  class TestCanTraffic < Minitest::Test
    # The robot block starts at line 10 of models/profiles/base.rb (four libraries).
    # An app bus model of CAN frames, written as common_models writes its
    # own (no can_id), and one of another message type.
    BUS_MODELS = {
      'models/devices/bus.rb' => <<~RUBY,
        module MyApp
          module Devices
            module Bus
              import_types_from 'canbus'
              import_types_from 'iodrivers_base'
              com_bus_type 'CAN', message_type: '/canbus/Message'
              com_bus_type 'Serial', message_type: '/iodrivers_base/RawPacket'
            end
          end
        end
      RUBY
      'models/orogen/buses.orogen' => <<~RUBY,
        name 'buses'
        import_types_from 'canbus'
        import_types_from 'iodrivers_base'
        task_context 'CANTask' do
          input_port 'can_in', '/canbus/Message'
          output_port 'can_out', '/canbus/Message'
        end
        task_context 'SerialTask' do
          input_port 'raw_in', '/iodrivers_base/RawPacket'
          output_port 'raw_out', '/iodrivers_base/RawPacket'
        end
      RUBY
      'models/orogen/buses.rb' => <<~RUBY
        require 'models/devices/bus'
        Syskit.extend_model(OroGen.buses.CANTask) { driver_for MyApp::Devices::Bus::CAN, as: 'can' }
        Syskit.extend_model(OroGen.buses.SerialTask) { driver_for MyApp::Devices::Bus::Serial, as: 'serial' }
      RUBY
    }.freeze
    LIBRARIES = %w[imu temp canbus buses].freeze

    def robot_of(robot)
      load_app(my_app(robot, BUS_MODELS, libraries: LIBRARIES)).profiles.values.first.robot
    end

    def problem(robot)
      root = my_app(robot, BUS_MODELS, libraries: LIBRARIES)
      [load_problem(root), root]
    end

    def test_frames_and_bitrate_are_recorded_on_the_bundled_can_bus
      robot = robot_of(<<~RUBY)
        com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(500_000)
        through 'can0' do
          device(Devices::TemperatureSensor, as: 't')
            .can_id(0x300, 0x7f0)
            .frame(0x181, bytes: 8, period: 0.001)
            .frame(0x18FF0001, bytes: 4, period: 0.1, deadline: 0.05, jitter: 0.002)
        end
      RUBY
      bus = robot.find_device('can0')
      assert_equal [500_000, Rational(7, 10)], [bus.bitrate, bus.warn_above]
      assert_equal 'models/profiles/base.rb', bus.bitrate_location.relative_path(Syskit.app.root)
      first, second = robot.find_device('t').can_frames
      assert_equal [0x181, false, 8, Rational(1, 1000), Rational(1, 1000), 0, 't'],
                   first.to_a.first(7)
      assert_equal [true, Rational(1, 20), Rational(1, 500)], [second.extended, second.deadline, second.jitter]
      assert_equal 14, first.location.lineno
      assert_equal [first, second], bus.frames_on_wire
    end

    def test_an_app_can_bus_model_without_can_id_carries_frames
      robot = robot_of(<<~RUBY)
        com_bus(Devices::Bus::CAN, as: 'can0').bitrate(250_000, warn_above: 0.5)
        through 'can0' do
          device(Devices::TemperatureSensor, as: 't').frame(0x10, bytes: 2, period: 1)
        end
      RUBY
      assert_equal [250_000, 0.5r], [robot.find_device('can0').bitrate, robot.find_device('can0').warn_above]
      assert_equal 1, robot.find_device('can0').frames_on_wire.size
    end

    def test_frames_of_a_bus_attached_to_a_bus_travel_on_the_outer_bus
      robot = robot_of(<<~RUBY)
        com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(250_000)
        through 'can0' do
          device(Devices::TemperatureSensor, as: 't').frame(0x10, bytes: 2, period: 1)
          com_bus(Devices::Bus::CAN, as: 'inner')
        end
        through 'inner' do
          device(Devices::TemperatureSensor, as: 'u').frame(0x11, bytes: 2, period: 1)
        end
      RUBY
      inner = robot.find_device('inner')
      assert_equal 'can0', inner.carrier.name
      assert_equal(%w[t u], robot.find_device('can0').frames_on_wire.map(&:device))
    end

    def test_declaration_errors
      {
        ".frame(0x181, bytes: 9, period: 0.01)\n" => [/frame\(385, \.\.\.\) on device 't': bytes: 9/, /0 to 8/],
        ".frame(0x181, bytes: 8, period: 0)\n" => [/period: 0 is not a positive number/, /period: 0.01/],
        ".frame(0x181, bytes: 8, period: 0.01, jitter: -0.001)\n" => [/jitter: -0.001/, /jitter: takes seconds/],
        ".frame(0x2000_0000, bytes: 8, period: 0.01)\n" => [/536870912 is not a CAN identifier/, /29 bits/],
        ".frame(0x181, period: 0.01)\n" => [/frame on device 't' needs bytes:/, /frame\(0x181, bytes: 8/],
        ".frame(0x181, bytes: 8, priod: 0.01)\n" => [/has no option priod: \(did you mean 'period'\?\)/,
                                                     /frame takes \(id, bytes:, period:/]
      }.each do |call, (message, hint)|
        error, root = problem("com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\n" \
                              "through('can0') { device(Devices::TemperatureSensor, as: 't')\n  #{call} }\n")
        assert_reported error, message, at: 'models/profiles/base.rb:12', hint: hint, root: root
        @loaded_apps.pop.unload
      end
    end

    def test_a_frame_on_a_bus_that_is_not_can
      error, root = problem(<<~RUBY)
        com_bus Devices::Bus::Serial, as: 'serial0'
        through 'serial0' do
          device(Devices::TemperatureSensor, as: 't').frame(0x181, bytes: 8, period: 0.01)
        end
      RUBY
      assert_reported error, %r{device 't' is attached to bus 'serial0', whose messages are not /canbus/Message},
                      at: 'models/profiles/base.rb:12', hint: /through 'can0' do/, root: root
    end

    def test_a_frame_on_a_device_not_attached
      error, root = problem("device(Devices::TemperatureSensor, as: 't').frame(0x181, bytes: 8, period: 0.01)\n")
      assert_reported error, /device 't' is attached to no bus: frame is for devices on a CAN bus/,
                      at: 'models/profiles/base.rb:10', root: root
    end

    def test_bitrate_errors
      {
        "com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(2_000_000)\n" =>
          [/bitrate on bus 'can0': 2000000 is not a CAN bitrate/, /up to 1_000_000/],
        "com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(5e5)\n" =>
          [/500000.0 is not a CAN bitrate/, /bitrate\(500_000\)/],
        "com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(500_000, warn_above: 70)\n" =>
          [/warn_above: 70 on bus 'can0' is not a fraction/, /0.6 for 60 %/],
        "com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(500_000, warn: 0.6)\n" =>
          [/bitrate on bus 'can0' has no option warn:/, /warn_above: 0.6/],
        "com_bus(Devices::Bus::Serial, as: 'serial0').bitrate(500_000)\n" =>
          [%r{MyApp::Devices::Bus::Serial does not carry /canbus/Message frames}, /for CAN buses/]
      }.each do |robot, (message, hint)|
        error, root = problem(robot)
        assert_reported error, message, at: 'models/profiles/base.rb:10', hint: hint, root: root
        @loaded_apps.pop.unload
      end
    end

    def test_the_bitrate_of_a_bus_attached_to_a_bus_belongs_to_the_outer_one
      error, root = problem(<<~RUBY)
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through 'can0' do
          com_bus(Devices::Bus::CAN, as: 'inner').bitrate(250_000)
        end
      RUBY
      assert_reported error, /inner is attached to bus 'can0': its frames travel on can0's wire/,
                      at: 'models/profiles/base.rb:12', hint: /declare the bitrate of can0/, root: root
    end

    def test_a_misspelled_bitrate_is_suggested
      error, root = problem("com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrat(500_000)\n")
      assert_reported error, /bus 'can0' has no 'bitrat' \(did you mean 'bitrate'\?\)/,
                      at: 'models/profiles/base.rb:10', root: root
    end
  end
end
