# frozen_string_literal: true

require 'helper'

module Syskit
  # Declaration-time errors of robot blocks (SPEC 5 and 11): what is wrong,
  # the user's line, and what to write instead.
  class TestRobotDeclarations < Minitest::Test
    # The robot block's first line in the profile written by my_app.
    ROBOT = 'models/profiles/base.rb:9'

    def problem(robot, **options)
      root = my_app(robot, **options)
      [load_problem(root), root]
    end

    def test_device_without_a_name
      error, root = problem("device(Devices::IMU)\n")
      assert_reported error, /a device needs a name/, at: ROBOT, hint: /device\(Model, as: 'name'\)/, root: root
    end

    def test_duplicate_device_name
      error, root = problem("device(Devices::IMU, as: 'imu')\ndevice(Devices::IMU, as: 'imu')\n")
      assert_reported error, %r{a device named 'imu' is already declared at models/profiles/base.rb:9},
                      at: 'models/profiles/base.rb:10', hint: /its own name/, root: root
    end

    def test_invalid_device_name
      error, root = problem("device(Devices::IMU, as: 'My IMU')\n")
      assert_reported error, /'My IMU' is not a valid device name/, at: ROBOT, hint: /lower-case/, root: root
    end

    def test_a_device_name_may_start_with_a_capital_as_in_syskit
      root = my_app("device(Devices::IMU, as: 'IMU')\n")
      load_app(root)
      assert_equal 'IMU', MyApp::Profiles::Base.IMU_dev.device.name
    end

    def test_a_data_service_is_not_a_device
      services = <<~RUBY
        module MyApp
          module Services
            data_service_type 'Pose'
          end
        end
      RUBY
      root = my_app("device(Services::Pose, as: 'pose')\n", { 'models/services/pose.rb' => services })
      assert_reported load_problem(root), /device expects a device model.*got MyApp::Services::Pose \(a data service\)/,
                      at: ROBOT, root: root
    end

    def test_a_bus_model_is_declared_with_com_bus
      error, root = problem("device(CommonModels::Devices::Bus::CAN, as: 'can0')\n")
      assert_reported error, /CommonModels::Devices::Bus::CAN is a communication bus/,
                      at: ROBOT, hint: /com_bus CommonModels::Devices::Bus::CAN, as: 'name'/, root: root
    end

    def test_com_bus_needs_a_bus_model
      error, root = problem("com_bus Devices::IMU, as: 'can0'\n")
      assert_reported error, /com_bus expects a bus model \(com_bus_type\), got MyApp::Devices::IMU \(a device\)/,
                      at: ROBOT, root: root
    end

    def test_unknown_device_option_is_rejected
      error, root = problem("device(Devices::IMU, as: 'imu', period: 0.1)\n")
      assert_reported error, /unknown option\(s\) period:/, at: ROBOT, hint: /chained calls \(.with_conf, .period/,
                                                            root: root
    end

    def test_client_to_bus_outside_a_bus
      error, root = problem("device(Devices::IMU, as: 'imu', client_to_bus: false)\n")
      assert_reported error, /client_to_bus: only applies to devices attached to a bus/,
                      at: ROBOT, hint: /through 'bus_name' do/, root: root
    end

    def test_through_an_unknown_bus
      error, root = problem("com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\nthrough 'can1' do\nend\n")
      assert_reported error, /no bus named 'can1' \(did you mean 'can0'\?\)/,
                      at: 'models/profiles/base.rb:10', hint: /buses of this robot: can0/, root: root
    end

    def test_through_a_device_that_is_not_a_bus
      error, root = problem("device(Devices::IMU, as: 'imu')\nthrough 'imu' do\nend\n")
      assert_reported error, /device 'imu' is not a communication bus/, at: 'models/profiles/base.rb:10', root: root
    end

    def test_a_device_that_neither_reads_nor_writes
      robot = <<~RUBY
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through 'can0' do
          device(Devices::TemperatureSensor, as: 't', client_to_bus: false, bus_to_client: false)
        end
      RUBY
      error, root = problem(robot)
      assert_reported error, /would neither read from nor write to bus 'can0'/,
                      at: 'models/profiles/base.rb:11', hint: /drop one of the two options/, root: root
    end

    def test_a_bus_attached_through_itself
      robot = <<~RUBY
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        com_bus CommonModels::Devices::Bus::CAN, as: 'can1'
        through 'can0' do
          device(Devices::TemperatureSensor, as: 't')
        end
        can0_dev = nil
      RUBY
      root = my_app(robot)
      app = load_app(root, problems: true)
      bus0, bus1 = MyApp::Profiles::Base.syskit_profile.robot.each_master_device.first(2)
      bus1.attach_to(bus0)
      error = assert_raises(NetworkError) { bus0.attach_to(bus1) }
      assert_match(/attaching bus 'can0' to bus 'can1' makes a cycle: can0 -> can1 -> can0/, error.message)
      assert_equal File.expand_path(__FILE__), error.location.path
      assert_empty app.problems.grep(NetworkError)
    end

    # SPEC 1: can_id stores what it is given (the seed's own test sets
    # can_id(10, 20)); a filter no frame can pass is a check warning at
    # the line that sets it.
    def test_can_id_that_can_never_match_is_stored_and_a_check_warning
      robot = <<~RUBY
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through 'can0' do
          device(Devices::TemperatureSensor, as: 't').prefer_deployed_tasks('t')
            .can_id(0x1234, 0x00ff)
          device(Devices::TemperatureSensor, as: 'u').can_id(0x34, 0xff).prefer_deployed_tasks('u')
        end
      RUBY
      root = my_app(robot, 'config/robots/default.rb' => <<~RUBY)
        using_task_library 'temp'
        Syskit.conf.use_deployment 'test_canbus'
        Syskit.conf.use_deployment OroGen.temp.Task => 't'
        Syskit.conf.use_deployment OroGen.temp.Task => 'u'
      RUBY
      load_app(root)
      assert_equal [0x1234, 0xff], MyApp::Profiles::Base.t_dev.device.can_id
      @loaded_apps.pop.unload
      out, = run_cli('check', '--app', root)
      assert_match(Regexp.new("^models/profiles/base.rb:12: warning: device 't' on bus 'can0' has a filter that can " \
                              'never match \(id 0x1234 mask 0xFF\): the id has bits outside the mask ' \
                              '\(id & mask = 0x34\), so no frame reaches it\n  hint: .*e.g. can_id\(0x1234, 0x12FF\)$'),
                   out)
      # It receives no frame, so it overlaps no other device.
      refute_match(/overlapping/, out)
      assert_match(/0 error\(s\), 1 warning\(s\)/, out)
    end

    def test_can_id_beyond_29_bits
      robot = <<~RUBY
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through 'can0' do
          device(Devices::TemperatureSensor, as: 't').can_id(0x2000_0000)
        end
      RUBY
      error, root = problem(robot)
      assert_reported error, /the id 0x20000000 does not fit in 29 bits/, at: 'models/profiles/base.rb:11', root: root
    end

    def test_can_id_on_a_device_that_is_not_attached
      robot = <<~RUBY
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        device(Devices::TemperatureSensor, as: 't').can_id(0x12)
      RUBY
      error, root = problem(robot)
      assert_reported error, Regexp.new(Regexp.escape("device 't' has no 'can_id': it is on no bus, and can_id is " \
                                                      'for devices attached to a CommonModels::Devices::Bus::CAN bus')),
                      at: 'models/profiles/base.rb:10',
                      hint: /\Adeclare t in a through 'bus_name' do \.\.\. end block\z/, root: root
    end

    def test_invalid_chained_values
      cases = {
        ".prefer_deployed_tasks(3)\n" => [/prefer_deployed_tasks expects regexps or names, got 3/,
                                          %r{prefer_deployed_tasks\(/forward/\)}],
        ".with_conf\n" => [/with_conf needs at least one section name/, /with_conf\('default', 'forward'\)/],
        ".period(-1)\n" => [/invalid period -1 for device 'imu'/, /period takes a positive number of seconds/],
        ".doc(3)\n" => [/invalid doc 3 for device 'imu'/, /doc takes a string/]
      }
      assert_each_reported(cases.transform_keys { |call| "device(Devices::IMU, as: 'imu')\n  #{call}" },
                           at: 'models/profiles/base.rb:10')
    end

    # Each robot block of +cases+ (robot => [message, hint, location]) fails
    # to load with that message and hint, at that location or +at+.
    def assert_each_reported(cases, at: nil)
      cases.each do |robot, (message, hint, location)|
        error, root = problem(robot)
        assert_reported error, message, at: location || at, hint: hint, root: root
        @loaded_apps.pop.unload
      end
    end

    # can_id's filter takes (id, mask = id): a value it refuses names the
    # call and its parameters, as does Ruby's refusal of a third argument.
    def test_invalid_can_id_arguments
      cases = {
        "can_id('a', 2)" => [/can_id\("a", 2\) on device 't': the id must be an integer, got "a"/,
                             /can_id takes \(id, mask = \.\.\.\)/],
        'can_id(1, 0x4000_0000)' => [/can_id\(1, 1073741824\) on device 't': the mask 0x40000000 does not fit/,
                                     /can_id takes \(id, mask = \.\.\.\)/],
        'can_id(1, 2, 3)' => [/\Acan_id: wrong number of arguments \(given 3, expected 0\.\.2\)/,
                              /\Acan_id takes \(id, mask = \.\.\.\)\z/]
      }
      robots = cases.transform_keys do |call|
        <<~RUBY
          com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
          device(Devices::TemperatureSensor, as: 't').attach_to('can0')
            .#{call}
        RUBY
      end
      assert_each_reported(robots, at: 'models/profiles/base.rb:11')
    end

    # Ruby refuses these calls before the statement runs; the message
    # names the statement and the hint says what it takes.
    def test_a_call_ruby_refuses_names_the_statement
      cases = {
        "device(Devices::IMU, 'imu')\n" =>
          [/\Adevice: wrong number of arguments \(given 2, expected 1\)/,
           /\Adevice takes \(model, as: \.\.\., using: \.\.\., doc: \.\.\., \*\*options\)\z/, ROBOT],
        "device(Devices::IMU, as: 'imu')\n  .period(0.1, 2)\n" =>
          [/\Aperiod: wrong number of arguments \(given 2, expected 0\.\.1\)/, /\Aperiod takes \(seconds = \.\.\.\)\z/,
           'models/profiles/base.rb:10'],
        "com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\nthrough('can0', true) { }\n" =>
          [/\Athrough: wrong number of arguments \(given 2, expected 1\)/, /\Athrough takes \(bus_name, &block\)\z/,
           'models/profiles/base.rb:10']
      }
      assert_each_reported(cases)
    end

    def test_unknown_statement_in_a_robot_block
      error, root = problem("devise(Devices::IMU, as: 'imu')\n")
      assert_reported error, /unknown statement 'devise' in a robot block \(did you mean 'device'\?\)/,
                      at: ROBOT, hint: /device, com_bus and through/, root: root
    end

    def test_com_bus_with_a_block_attaches_the_devices
      root = my_app(<<~RUBY)
        com_bus(CommonModels::Devices::Bus::CAN, as: 'can0') do
          device(Devices::TemperatureSensor, as: 't').can_id(1)
        end
      RUBY
      load_app(root)
      assert_equal 'can0', MyApp::Profiles::Base.t_dev.device.bus.name
    end

    def test_attach_to_does_what_through_does
      root = my_app(<<~RUBY)
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        device(Devices::TemperatureSensor, as: 't').attach_to('can0', client_to_bus: false).can_id(1)
      RUBY
      load_app(root)
      device = MyApp::Profiles::Base.t_dev.device
      assert_equal ['can0', false, true], [device.bus.name, device.client_to_bus?, device.bus_to_client?]
      assert_equal [1, 1], device.can_id
    end

    # Syskit's forms on the bus object itself.
    def test_through_and_device_on_a_bus_object
      root = my_app(<<~RUBY)
        can0 = com_bus(CommonModels::Devices::Bus::CAN, as: 'can0')
        can0.through do
          device(Devices::TemperatureSensor, as: 'a').can_id(1)
        end
        can0.device(Devices::TemperatureSensor, as: 'b', client_to_bus: false).can_id(2)
      RUBY
      load_app(root)
      a = MyApp::Profiles::Base.a_dev.device
      b = MyApp::Profiles::Base.b_dev.device
      assert_equal [%w[can0 can0], [true, false]], [[a.bus.name, b.bus.name], [a.client_to_bus?, b.client_to_bus?]]
      assert_equal 'models/profiles/base.rb:13', b.declared_at.to_s(root)
      assert_equal %w[a b], a.bus.each_attached_device.map(&:name)
    end

    def test_chainable_settings_are_recorded
      root = my_app(<<~RUBY)
        device(Devices::IMU, as: 'imu').period(0.01).burst(3).sample_size(64).doc('the IMU')
          .with_conf('default', 'fast').prefer_deployed_tasks(/imu/, 'imu2')
      RUBY
      load_app(root)
      device = MyApp::Profiles::Base.imu_dev.device
      assert_equal [0.01, 3, 64, 'the IMU', %w[default fast], [/imu/, 'imu2']],
                   [device.period, device.burst, device.sample_size, device.doc, device.conf, device.deployment_hints]
    end

    # A chain of settings on one line is one place: one frozen Location
    # (a 10,000-device robot made four per device), another line another.
    def test_settings_chained_on_one_line_share_their_location
      root = my_app(<<~RUBY)
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        device(Devices::TemperatureSensor, as: 't').attach_to('can0').can_id(1).with_conf('default', 'x')
          .prefer_deployed_tasks('t')
        device(Devices::TemperatureSensor, as: 'u').attach_to('can0')
          .can_id(2, 0x7ff)
      RUBY
      load_app(root)
      device = MyApp::Profiles::Base.t_dev.device
      assert device.declared_at.frozen?
      assert_same device.declared_at, device.dsl_attribute_location(:can_id)
      assert_same device.declared_at, device.conf_location
      assert_equal 'models/profiles/base.rb:11', device.deployment_hints_location.to_s(root)
      refute_same device.declared_at, device.deployment_hints_location
      other = MyApp::Profiles::Base.u_dev.device
      assert_equal [[2, 0x7ff], 'models/profiles/base.rb:13'],
                   [other.can_id, other.dsl_attribute_location(:can_id).to_s(root)]
    end
  end
end
