# frozen_string_literal: true

require 'helper'
require 'generators/gen_test_helpers'

module Syskit
  # `syskit gen orogen`, `gen tasklib` and `gen orogenconf`: what an app
  # writes of its task libraries.
  class TestGenOrogen < Minitest::Test
    include GenTestHelpers

    # As in Rock, an app's extension of canbus replaces the bundled one: it
    # starts from it with a require, and its test fails without it.
    def test_an_extension_of_the_bundled_canbus_starts_from_it
      app, = new_app
      gen('orogen', 'canbus', chdir: app)
      extension = File.join(app, 'models', 'orogen', 'canbus.rb')
      text = File.read(extension)
      assert_includes text, "# This file takes the place of common_models/models/orogen/canbus.rb,\n" \
                            "# the canbus extension bundled with syskit, as an app's extension file\n"
      assert_includes text, "  # Declared by common_models/models/orogen/canbus (required above):\n  " \
                            "#   driver_for CommonModels::Devices::Bus::CAN, as: 'can'\n"
      out, err, status = syskit_test('test/orogen/test_canbus.rb', chdir: app)
      assert status.success?, "#{out}#{err}"

      File.write(extension, text.sub(/^require .*\n/, ''))
      out, _, status = syskit_test('test/orogen/test_canbus.rb', chdir: app)
      assert_equal 1, status.exitstatus
      assert_match(/^canbus::Task no longer drives CommonModels::Devices::Bus::CAN \(keep the require of /, out)

      # Generated again over a file without the require, it has it again.
      gen('orogen', 'canbus', '--force', chdir: app)
      assert_equal text, File.read(extension)
    end

    MOTOR_LIB = <<~RUBY
      name 'motor'
      import_types_from 'canbus'
      task_context 'Task' do
        property 'can_id', 'int'
        property 'can_mask', 'int'
        input_port 'from_bus', '/canbus/Message'
        output_port 'to_bus', '/canbus/Message'
      end
      task_context 'Probe' do
        input_port 'frames', '/canbus/Message'
      end
    RUBY

    # The seed's driver of a device on a CAN bus, as a user adds it to the
    # generated extension: driver_for, and a configure that reads can_id.
    MOTOR_DRIVER = <<~RUBY
      require 'models/devices/motor'
      Syskit.extend_model OroGen.motor.Task do
        driver_for AwesomeRobot::Devices::Motor, as: 'motor'

        def configure
          super
          id, mask = motor_dev.can_id
          properties.can_id = id
          properties.can_mask = mask
        end
      end
    RUBY

    # A task with ports of a bus's message type gets the seed's test form
    # (a stub bus, a device attached with its settings), which checks the
    # task itself before and after it declares the device it drives.
    def test_the_test_of_a_bus_device_driver_attaches_its_device_to_a_stub_bus
      app, = new_app
      File.write(File.join(app, 'models', 'orogen', 'motor.orogen'), MOTOR_LIB)
      gen('orogen', 'motor', chdir: app)
      gen('dev', 'motor', chdir: app)
      assert_file app, 'test/orogen/test_motor.rb',
                  "    it 'is configurable on a CAN bus' do
      " \
                  "bus = syskit_stub_com_bus(CommonModels::Devices::Bus::CAN)\n      " \
                  "dev = syskit_stub_attached_device(bus).can_id(0x100, 0x7ff)\n      " \
                  "assert_kind_of OroGen.motor.Task, syskit_stub_deploy_and_configure(dev)\n",
                  "      dev = syskit_stub_attached_device(bus, client_to_bus: false).can_id(0x100, 0x7ff)\n"
      [nil, MOTOR_DRIVER].each do |extension|
        File.write(File.join(app, 'models', 'orogen', 'motor.rb'), extension) if extension
        out, err, status = syskit_test('test/orogen/test_motor.rb', chdir: app)
        assert status.success?, "#{out}#{err}"
        assert_match(/^2 runs, 2 assertions, 0 failures, 0 errors, 0 skips/, out)
      end
    end

    # The same driver tested with a device on no bus: the message says so
    # and how to attach it.
    def test_a_stub_device_on_no_bus_says_how_to_attach_it
      app, = new_app
      File.write(File.join(app, 'models', 'orogen', 'motor.orogen'), MOTOR_LIB)
      gen('dev', 'motor', chdir: app)
      File.write(File.join(app, 'models', 'orogen', 'motor.rb'), MOTOR_DRIVER)
      File.write(File.join(app, 'test', 'test_alone.rb'),
                 "using_task_library 'motor'\nmodule OroGen\n  describe motor.Task do\n    " \
                 "it { is_configurable }\n  end\nend\n")
      out, _err, status = syskit_test('test/test_alone.rb', chdir: app)
      refute status.success?
      assert_includes out, "device 'dev0' has no 'can_id': it is on no bus, and can_id is for devices attached " \
                           "to a CommonModels::Devices::Bus::CAN bus\n  hint: in a test, make it on a stub bus: " \
                           'bus = syskit_stub_com_bus(CommonModels::Devices::Bus::CAN); ' \
                           'dev = syskit_stub_attached_device(bus).can_id(...)'
    end

    def test_a_new_task_library_neither_hides_another_nor_takes_a_bad_name
      app, = new_app
      before = files_of(app)
      { %w[canbus] => "there is already a task library 'canbus' (bundled with syskit): a new one in the app " \
                      "would hide it\n  hint: give the new library another name, or extend this one with: " \
                      'syskit gen orogen canbus',
        %w[gps-ublox] => "'gps-ublox' is not a task library name\n  hint: give a name of letters, digits and _",
        %w[gps_ublox::f9] => "'f9' is not a task context name\n  hint: task contexts are named as Ruby constants",
        %w[../gps] => "'../gps' contains '..'" }.each do |args, message|
        assert_includes refused('tasklib', *args, chdir: app), message, args.join(' ')
      end
      assert_equal before, files_of(app)
      assert_match %r{create models/orogen/imu\.orogen}, gen('tasklib', 'imu', chdir: app)
      assert_file app, 'models/orogen/imu.orogen', "task_context 'Task' do\n"
      assert_match(%r{these files exist, nothing was written: models/orogen/imu\.orogen},
                   refused('tasklib', 'imu', chdir: app))
    end

    def test_orogenconf_names_a_task_model_of_a_known_library
      app, = new_app
      before = files_of(app)
      assert_equal "'canbus' is not the name of a task model\n  hint: give the library and the task, as in the name " \
                   "of the configuration file: syskit gen orogenconf gps_ublox::Task\n",
                   refused('orogenconf', 'canbus', chdir: app)
      assert_equal "task library 'canbus' has no task 'canbus::Tsk' (did you mean 'canbus::Task'?)\n  " \
                   "hint: its tasks are canbus::InterfaceTask, canbus::Task\n",
                   refused('orogenconf', 'canbus::Tsk', chdir: app)
      assert_match(/\Ano task library 'canbs' \(did you mean 'canbus'\?\)\n  hint: there is no canbs.orogen/,
                   refused('orogenconf', 'canbs::Task', chdir: app))
      assert_equal before, files_of(app)
    end

    def test_gen_orogen_of_a_library_with_no_spec_says_how_to_start_one
      app, = new_app
      error = refused('orogen', 'dvl_teledyne', chdir: app)
      assert_match(/\Ano task library 'dvl_teledyne'\n  hint: there is no dvl_teledyne\.orogen in /, error)
      assert error.end_with?("; to start a new task library: syskit gen tasklib dvl_teledyne\n"), error
    end

    def test_errors_of_a_task_library_point_at_its_file
      app, = new_app
      File.write(File.join(app, 'models', 'orogen', 'broken.orogen'), "name 'broken'\ntask_contxt 'Task' do\nend\n")
      error = refused('orogen', 'broken', chdir: app)
      assert_match(%r{\Amodels/orogen/broken\.orogen:2: .*task_contxt}, error)
      refute File.exist?(File.join(app, 'models', 'orogen', 'broken.rb'))
    end
  end
end
