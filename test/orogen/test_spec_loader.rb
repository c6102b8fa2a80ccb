# frozen_string_literal: true

require 'helper'

module Syskit
  # .orogen files in oroGen's own syntax, written the way Rock driver
  # packages write them (SPEC 2).
  class TestSpecLoader < Minitest::Test
    # Statements and styles seen in real oroGen projects.
    DRIVER_SPEC = <<~RUBY
      # frozen_string_literal: true

      name "serial_imu"
      version "1.0"

      using_library "serial_imu", typekit_link: false
      import_types_from "std"
      import_types_from "base"
      import_types_from "serial_imu/Config.hpp"
      import_types_from "serial_imuTypes.hpp"
      using_task_library "iodrivers_base"

      # Driver of a serial IMU
      task_context "Task", subclasses: "iodrivers_base::Task" do
          doc "reads the IMU"
          needs_configuration

          property("config", "/serial_imu/Config").
              doc "the device configuration"
          property "rate", "double", 100.0
          property("calibration", "/std/vector</double>")
          attribute "last_error", "/std/string"

          input_port("commands", "/serial_imu/Command").
              needs_buffered_connection(10).
              doc "raw commands"
          output_port("samples", "base/samples/IMUSensors").
              doc("calibrated samples")
          output_port "status", "/serial_imu/Status"

          operation("reset").
              returns("bool", "true on success").
              argument("hard", "bool", "power-cycle the device").
              doc "resets the device"

          exception_states :SENSOR_TIMEOUT
          error_states "CHECKSUM_ERROR"
          runtime_states :CALIBRATING
          reports :HOMING
          port_driven "io_raw_in"
          fd_driven
          worstcase_processing_time 0.01
      end

      task_context "test::Replay", subclasses: "Task" do
          periodic 0.1
      end

      using_task_library "logger"
      deployment "serial_imu_test" do
          do_not_install
          t = task("imu", "serial_imu::Task").
              periodic(0.01).
              realtime.
              priority(90)

          add_default_logger
          if !corba_enabled?
              browse t
          end
      end
    RUBY

    def load_spec(spec = DRIVER_SPEC, name: 'serial_imu')
      root = my_app(nil, "models/orogen/#{name}.orogen" => spec)
      app = load_app(root, problems: true)
      app.using_task_library(name)
      app
    rescue Syskit::Error => e
      e
    end

    def test_a_real_world_spec_loads
      app = load_spec
      assert_kind_of App, app
      task = OroGen.serial_imu.Task
      assert_equal 'serial_imu::Task', task.name
      assert task < OroGen.iodrivers_base.Task
      assert_equal %w[commands io_raw_in io_raw_out io_read_listener io_write_listener samples state status],
                   task.ports.keys.sort
    end

    def test_a_real_world_spec_declares_its_ports
      load_spec
      task = OroGen.serial_imu.Task
      assert_equal 10, task.find_port('commands').buffer_size
      assert task.find_port('io_raw_in').reliable?
      assert_equal '/base/samples/IMUSensors', task.find_port('samples').type.name
      assert task.find_port('status').type.opaque?, 'types from headers stay opaque'
    end

    def test_a_real_world_spec_declares_its_properties_states_and_operations
      load_spec
      task = OroGen.serial_imu.Task
      assert_equal 100.0, task.property_declarations['rate'].initial_value
      assert_includes task.property_declarations.keys, 'io_port'
      assert_equal 0.01, task.worstcase_processing_time
      assert_equal %w[SENSOR_TIMEOUT], task.spec.states[:exception_states]
      assert_equal %w[CALIBRATING HOMING], task.spec.states[:runtime_states]
      assert_equal %w[hard], task.spec.operations['reset'].arguments.map(&:first)
    end

    def test_namespaced_task_contexts_and_relative_subclasses
      load_spec
      replay = OroGen.serial_imu.test.Replay
      assert_equal 'serial_imu::test::Replay', replay.name
      assert replay < OroGen.serial_imu.Task
      assert_equal OroGen.serial_imu.Task.ports.keys.sort, replay.ports.keys.sort
    end

    def test_deployments_are_registered
      app = load_spec
      deployment = app.orogen.find_deployment('serial_imu_test')
      assert_equal([['imu', OroGen.serial_imu.Task]], deployment.task_activities.map { |t| [t.name, t.model] })
    end

    def test_the_bundled_canbus_library
      app = load_app(my_app)
      app.using_task_library('canbus')
      task = OroGen.canbus.Task
      assert task.find_port('in').multiplexes?
      assert_equal([[/\w+/, :output, '/canbus/Message']],
                   task.dynamic_ports.map { |p| [p.pattern, p.direction, p.type.name] })
      assert_equal %w[bus_in can], task.services.keys.sort
    end

    # The interface of Rock's canbus component, in this gem's words.
    def test_the_bundled_canbus_library_is_rocks_canbus
      app = load_app(my_app)
      app.using_task_library('canbus')
      task = OroGen.canbus.Task
      assert_equal %w[unwatch watch], task.operations.keys.sort
      assert_equal %w[name id mask], task.operations['watch'].arguments.map(&:first)
      assert_equal %w[checkBusOkInterval device deviceType fd_activity_timeout outputPorts statsInterval],
                   task.property_declarations.keys.sort
      assert_equal %w[can_in can_out state], OroGen.canbus.InterfaceTask.ports.keys.sort
    end

    def test_the_bundled_canbus_deployment_and_types_are_rocks
      app = load_app(my_app)
      app.using_task_library('canbus')
      deployed = app.orogen.find_deployment('test_canbus').task_activities
      assert_equal([%w[can canbus::Task]], deployed.map { |t| [t.name, t.model.name] })
      assert_equal %i[SOCKET HICO HICO_PCI EASY_SYNC], ::Types.canbus.DRIVER_TYPE.values
      assert_equal %w[ports_name mask id], ::Types.canbus.CanOutputPort.fields.keys
    end

    def spec_error(spec)
      error = load_spec(spec, name: 'broken')
      assert_kind_of Syskit::Error, error
      error
    end

    def test_unknown_statement
      error = spec_error("name 'broken'\ntask_context 'Task' do\n  output_prot 'x', '/double'\nend\n")
      assert_reported error, /unknown statement 'output_prot' in task_context 'Task' \(did you mean 'output_port'\?\)/,
                      at: 'models/orogen/broken.orogen:3', hint: /the statements known here are .*output_port/,
                      root: Syskit.app.root
    end

    def test_unknown_top_level_statement
      error = spec_error("name 'broken'\ntask_contxt 'Task' do\nend\n")
      assert_reported error, /unknown statement 'task_contxt' in an .orogen file \(did you mean 'task_context'\?\)/,
                      at: 'models/orogen/broken.orogen:2', root: Syskit.app.root
    end

    def test_unknown_type_without_header_imports
      error = spec_error("name 'broken'\nimport_types_from 'canbus'\n" \
                         "task_context 'Task' do\n  output_port 'x', '/canbus/Mesage'\nend\n")
      assert_reported error, %r{unknown type /canbus/Mesage \(did you mean '/canbus/Message'},
                      at: 'models/orogen/broken.orogen:4', root: Syskit.app.root
    end

    # As oroGen does: a full task name loads its library.
    def test_a_full_task_name_loads_its_library
      app = load_spec("name 'mine'\ntask_context 'Task', subclasses: 'iodrivers_base::Task' do\nend\n" \
                      "deployment 'mine_test' do\n  task 'logs', 'logger::Logger'\nend\n", name: 'mine')
      assert_empty %w[iodrivers_base logger mine] - app.orogen.loaded_library_names
      assert_operator OroGen.mine.Task, :<, OroGen.iodrivers_base.Task
    end

    def test_subclass_of_a_library_that_does_not_exist
      error = spec_error("name 'broken'\ntask_context 'Task', subclasses: 'iodriver_base::Task' do\nend\n")
      assert_reported error, /no task library 'iodriver_base' \(did you mean 'iodrivers_base'\?\)/,
                      at: 'models/orogen/broken.orogen:2', root: Syskit.app.root
    end

    def test_duplicate_port
      error = spec_error("name 'broken'\ntask_context 'Task' do\n  " \
                         "output_port 'x', '/double'\n  input_port 'x', '/double'\nend\n")
      assert_reported error, /broken::Task declares the port 'x' twice/, at: 'models/orogen/broken.orogen:4',
                                                                         root: Syskit.app.root
    end

    def test_project_name_that_does_not_match_the_file
      error = spec_error("name 'other'\n")
      assert_reported error, /broken.orogen declares the project name 'other'/,
                      at: 'models/orogen/broken.orogen:1', hint: /must be named other.orogen/, root: Syskit.app.root
    end

    def test_a_deployment_of_an_unknown_task
      error = spec_error("name 'broken'\ndeployment 'd' do\n  task('x', 'broken::Tsak')\nend\n")
      assert_reported error, /unknown task model 'broken::Tsak'/, at: 'models/orogen/broken.orogen:3',
                                                                  root: Syskit.app.root
    end

    def test_a_deployment_name_used_twice
      error = spec_error("name 'broken'\nusing_task_library 'canbus'\ndeployment 'test_canbus' do\nend\n")
      assert_reported error, /deployment 'test_canbus' is already declared/, at: 'models/orogen/broken.orogen:3',
                                                                             root: Syskit.app.root
    end

    def test_a_failed_library_can_be_reported_again
      load_spec("name 'broken'\nfoo\n", name: 'broken')
      assert_raises(SpecError) { Syskit.app.using_task_library('broken') }
    end

    # One cause, one error: a file that fails after a valid deployment is
    # loaded again when something asks for it, and its deployment was
    # "already declared" at its own line.
    def test_a_failed_spec_does_not_keep_its_deployments
      spec = "name 'cams'\ntask_context 'Task' do\nend\ndeployment 'cams' do\n  task 'cam', 'cams::Task'\nend\n" \
             "simple_deployment 'cam_simple', 'cams::Nope'\n"
      robot = "using_task_library 'cams'\nSyskit.conf.use_deployment 'cams'\n"
      root = my_app("device(Devices::IMU, as: 'imu')\n", 'models/orogen/cams.orogen' => spec,
                                                         'config/robots/default.rb' => robot)
      out, _, status = run_cli('check', '--app', root)
      assert_equal 1, status
      assert_equal "models/orogen/cams.orogen:7: unknown task model 'cams::Nope' (did you mean 'cams::Task'?)",
                   out.lines.first.chomp
      assert_match(/\A  hint: the task models known here are cams::Task, /, out.lines[1])
      refute_includes out, 'already declared'
      out, err, status = run_cli('plan', '--app', root, '--format', 'json')
      assert_equal [1, ''], [status, out]
      refute_includes err, 'already declared'
    end
  end
end
