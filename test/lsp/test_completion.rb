# frozen_string_literal: true

require_relative 'lsp_helper'

module Syskit
  # Completion: what may be typed where the line says what it expects.
  class TestLSPCompletion < Minitest::Test
    include SelfTest::LSPHelper

    def setup
      super
      @profile = example('models/profiles/live/base.rb')
    end

    def query
      @query ||= LSP::Completion.new(example_app)
    end

    # The items at the end of +typed+, written in place of the line of the
    # file that holds +replaced+.
    def complete(typed, replaced, path = @profile)
      lines = File.read(path).lines
      index = lines.index { |l| l.include?(replaced) } || flunk("#{replaced.inspect} is not in #{path}")
      lines[index] = "#{typed}\n"
      query.at(path, lines.join, index, typed.size)
    end

    def labels(items)
      items.map { |i| i[:label] }
    end

    def test_device_models_in_device_named_as_the_file_can_write_them
      items = complete('          device(', "device(Devices::GPS::Ublox::F9, as: 'gps')")
      assert_includes labels(items), 'Devices::GPS::Ublox::F9'
      refute_includes labels(items), 'CommonModels::Devices::Bus::CAN'
      f9 = items.find { |i| i[:label] == 'Devices::GPS::Ublox::F9' }
      assert_equal({ label: 'Devices::GPS::Ublox::F9', kind: 7, detail: 'device model',
                     documentation: "Ublox's 9th generation GNSS receivers (F9P, F9R)." }, f9)
    end

    def test_bus_models_in_com_bus
      items = complete('          com_bus(', "com_bus(CommonModels::Devices::Bus::CAN, as: 'can0'")
      assert_equal ['CommonModels::Devices::Bus::CAN', 'Devices::N2k::Bus'], labels(items).sort
    end

    def test_bus_names_in_through
      items = complete("          through '", "through 'can1' do")
      assert_equal %w[can0 n2k can1], labels(items)
      assert_equal [6, 'bus CommonModels::Devices::Bus::CAN'], items.first.values_at(:kind, :detail)
    end

    def test_task_libraries_in_using_task_library_loaded_or_not
      items = complete("using_task_library '", "using_task_library 'roboteq'")
      assert_includes labels(items), 'roboteq'
      logger = items.find { |i| i[:label] == 'logger' }
      assert_equal [9, 'task library', 'not loaded yet'], logger.values_at(:kind, :detail, :documentation)
      assert_match(/canbus::Task/, items.find { |i| i[:label] == 'canbus' }[:documentation])
    end

    def test_sections_of_the_driver_of_the_device_above_in_with_conf
      items = complete("            .with_conf('default', '", ".with_conf('default', 'aft')")
      assert_equal %w[default forward aft], labels(items)
      assert_equal [12, 'section of camera_gige::Task', 'exposure, frame_rate'],
                   items.first.values_at(:kind, :detail, :documentation)
    end

    def test_configurations_of_the_composition_of_the_definition_above_in_with_conf
      items = complete("          .with_conf('", ".with_conf('summer')")
      assert_equal [{ label: 'summer', kind: 12, detail: 'configuration of AwesomeRobot::Compositions::TemperatureWatch',
                      documentation: 'monitor: default, summer' }], items
    end

    def test_no_sections_when_the_configuration_file_cannot_be_read
      root = my_app("device(MyApp::Devices::IMU, as: 'imu')\n  .with_conf('default')\n",
                    'config/orogen/imu::Task.yml' => "--- name:default\nrate: [unclosed\n")
      app = load_app(root, problems: true, robots: [], everything: true, models: true)
      path = File.join(root, 'models/profiles/base.rb')
      text = File.read(path)
      line, character = position(text, "with_conf('default')", offset: 11)
      assert_empty LSP::Completion.new(app).at(path, text, line, character)
      assert_equal '**configuration** `default` of `imu::Task`: not declared',
                   LSP::Hover.new(app).at(path, text, line, character + 1)
    end

    def test_inputs_of_the_children_in_connect_to
      drive = example('models/compositions/drive.rb')
      items = complete('      position_child.position_samples_port.connect_to ', 'position_child.position', drive)
      assert_equal [{ label: 'follower_child.pose_port', kind: 5, detail: 'input /base/samples/RigidBodyState',
                      documentation: '' }], items
      speeds = complete('      follower_child.left_speed_port.connect_to ', 'follower_child.left', drive)
      assert_equal %w[left_child.speed_command_port right_child.speed_command_port], labels(speeds)
      assert_equal %w[left_speed_port pose_port right_speed_port state_port],
                   labels(complete('      follower_child.', 'follower_child.left', drive)).sort
    end

    def test_loaded_task_libraries_and_their_tasks_after_orogen
      libraries = complete('          device(OroGen.', "device(Devices::GPS::Ublox::F9, as: 'gps')")
      assert_includes labels(libraries), 'can_open'
      refute_includes labels(libraries), 'logger'
      tasks = complete('          device(OroGen.can_open.', "device(Devices::GPS::Ublox::F9, as: 'gps')")
      assert_equal %w[SyncTask], labels(tasks)
      assert_equal [7, 'task model'], tasks.first.values_at(:kind, :detail)
      assert_empty complete('          device(OroGen.nope.', "device(Devices::GPS::Ublox::F9, as: 'gps')")
    end

    def test_deployments_in_use_deployment
      robot = example('config/robots/default.rb')
      items = complete("Syskit.conf.use_deployment '", "use_deployment 'motors'", robot)
      assert_equal %w[cameras motors test_canbus], labels(items)
      assert_equal [9, 'deployment', 'forward_camera (camera_gige::Task), aft_camera (camera_gige::Task)'],
                   items.first.values_at(:kind, :detail, :documentation)
    end

    def test_nothing_where_the_line_expects_nothing_known
      assert_empty complete('          robot ', 'robot do')
      assert_empty complete('      nope_child.', 'follower_child.left', example('models/compositions/drive.rb'))
      assert_empty query.at(@profile, '', 0, 0)
      assert_empty query.at(@profile, File.read(@profile), 1000, 3)
    end

    def test_a_file_that_failed_to_load
      app, path = app_with_broken_profile
      completion = LSP::Completion.new(app)
      lines = File.read(path).lines
      index = lines.index { |l| l.include?("as: 'nope'") }
      lines[index] = "device(\n"
      assert_includes labels(completion.at(path, lines.join, index, 7)), 'Devices::IMU'
      lines[index] = "device(MyApp::Devices::IMU, as: 'x').with_conf('"
      assert_empty completion.at(path, lines.join, index, lines[index].size)
    end
  end
end
