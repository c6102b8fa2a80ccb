# frozen_string_literal: true

require_relative 'lsp_helper'

module Syskit
  # Hover: what the site's page of the thing under the cursor says, in short.
  class TestLSPHover < Minitest::Test
    include SelfTest::LSPHelper

    def setup
      super
      @profile = example('models/profiles/live/base.rb')
    end

    def query
      @query ||= LSP::Hover.new(example_app)
    end

    def hover(needle, path = @profile, **position)
      query_at(query, path, needle, **position)
    end

    def test_a_device_model_constant_shows_its_page_in_short
      text = hover('F9, as:')
      assert_match(/\A\*\*device model\*\* `AwesomeRobot::Devices::GPS::Ublox::F9`/, text)
      assert_includes text, "Ublox's 9th generation GNSS receivers"
      assert_includes text, '`pose_samples` output `/base/samples/RigidBodyState`'
      assert_includes text, 'Provides: `AwesomeRobot::Services::Position` (position_samples → pose_samples)'
      assert_includes text, 'Drivers: `gps_ublox::F9Task`'
      line = line_of(example('models/devices/gps/ublox/f9.rb'), "device_type 'F9'")
      assert_includes text, "Declared at `models/devices/gps/ublox/f9.rb:#{line}`"
    end

    def test_a_part_of_a_constant_path_is_the_module_it_names
      assert_match(/device model/, hover('Ublox::F9', offset: 7))
      text = hover('GPS::Ublox::F9')
      assert_match(/\A\*\*namespace\*\* `AwesomeRobot::Devices::GPS`/, text)
      assert_includes text, '`Ublox::F9` (device model)'
      refute_includes text, 'Camera'
    end

    def test_a_module_without_models_shows_nothing
      assert_nil query_at(query, @profile, 'Kernel', text: "Kernel.puts 'x'\n")
      assert_nil query_at(query, @profile, 'Comparable', text: "Comparable\n")
    end

    def test_a_bus_model_says_its_messages_and_where_it_comes_from
      text = hover('CAN, as:')
      assert_match(/\A\*\*bus model\*\* `CommonModels::Devices::Bus::CAN` \(from common_models/, text)
      assert_includes text, 'messages `/canbus/Message`'
    end

    def test_a_composition_shows_its_children_and_exports
      text = hover('Compositions::Drive', offset: 14)
      assert_match(/\A\*\*composition\*\* `AwesomeRobot::Compositions::Drive`/, text)
      assert_includes text, '`follower`: `navigation::PathFollower`'
      assert_includes text, 'Exports: `pose` input `/base/samples/RigidBodyState`'
    end

    def test_a_task_model_of_the_orogen_namespace
      text = hover('canbus.Task)', offset: 8)
      assert_match(/\A\*\*task model\*\* `canbus::Task`/, text)
      assert_match(/Ports:/, text)
      assert_match(/Drives: `can0`/, text)
    end

    def test_the_library_of_an_orogen_chain_and_of_using_task_library
      assert_match(/\A\*\*task library\*\* `canbus`\n\nTask models: `canbus::Task`/, hover('canbus.Task'))
      assert_match(/\A\*\*task library\*\* `roboteq`/, hover("'roboteq'", offset: 2))
    end

    def test_a_device_by_its_name_its_action_and_a_bus_by_through
      gps = hover("'gps'", offset: 1)
      assert_match(/\A\*\*device\*\* `gps` of `AwesomeRobot::Profiles::Live::Base`/, gps)
      assert_includes gps, 'model `AwesomeRobot::Devices::GPS::Ublox::F9` · driver `gps_ublox::F9Task`'
      assert_equal gps, hover('gps_dev')
      bus = hover("through 'can0'", offset: 10)
      assert_match(/\A\*\*bus\*\* `can0`/, bus)
      assert_includes bus, 'Two CAN drivers are loaded'
      assert_includes hover('temperature_sensor_dev'), 'through `can0`'
    end

    def test_an_action_of_another_profile_by_its_receiver
      other = <<~RUBY
        require 'models/profiles/base'
        module MyApp
          module Profiles
            profile 'Other' do
              define 'imu_too', Base.imu_dev
            end
          end
        end
      RUBY
      root = my_app("device(MyApp::Devices::IMU, as: 'imu')\n", 'models/profiles/other.rb' => other)
      app = load_app(root, robots: [], everything: true, models: true)
      path = File.join(root, 'models/profiles/other.rb')
      assert_match(/\A\*\*device\*\* `imu` of `MyApp::Profiles::Base`/, query_at(LSP::Hover.new(app), path, 'imu_dev'))
      assert_equal([[File.join(root, 'models/profiles/base.rb'), 9]],
                   query_at(LSP::Definition.new(app), path, 'imu_dev').map { |l| [l.path, l.lineno] })
    end

    def test_a_definition_by_its_action_and_its_name
      text = hover('watch_temperatures', offset: 2)
      assert_match(/\A\*\*definition\*\* `watch_temperatures_def` of `AwesomeRobot::Profiles::Live::Base`/, text)
      assert_includes text, 'model `AwesomeRobot::Compositions::TemperatureWatch`'
      assert_includes text, 'Alarms on the engine and water temperatures.'
    end

    def test_a_deployment_of_a_task_library_by_its_name
      text = query_at(query, example('config/robots/default.rb'), "'cameras'", offset: 2)
      assert_match(/\A\*\*deployment\*\* `cameras`/, text)
      assert_includes text, 'Tasks: `forward_camera` (`camera_gige::Task`), `aft_camera` (`camera_gige::Task`)'
      assert_includes text, 'Declared at `models/orogen/camera_gige.orogen:'
      assert_nil query_at(query, example('config/robots/default.rb'), "=> 'gps'", offset: 5)
    end

    def test_the_statements_of_an_orogen_file
      orogen = example('models/orogen/camera_gige.orogen')
      assert_match(/\A\*\*task model\*\* `camera_gige::Task`/,
                   query_at(query, orogen, "task_context 'Task'", offset: 15))
      assert_match(/\A\*\*task model\*\* `camera_gige::Task`/,
                   query_at(query, orogen, "'camera_gige::Task'", offset: 3))
      assert_match(/\A\*\*deployment\*\* `cameras`/, query_at(query, orogen, "deployment 'cameras'", offset: 13))
      assert_nil query_at(query, orogen, "task('forward_camera'", offset: 7)
    end

    def test_a_profile_by_its_name
      text = hover("profile 'Base'", offset: 10)
      assert_match(/\A\*\*profile\*\* `AwesomeRobot::Profiles::Live::Base`/, text)
      assert_includes text, 'Definitions: `drive_def`, `watch_temperatures_def`'
    end

    def test_a_configuration_section
      text = hover("'forward')", offset: 3)
      assert_match(/\A\*\*section\*\* `forward` of `camera_gige::Task`/, text)
      assert_includes text, 'Sets: `ip`'
      assert_includes text, 'Declared at `config/orogen/camera_gige::Task.yml:4`'
    end

    def test_a_named_configuration_of_a_definition_s_composition
      text = hover("with_conf('summer')", offset: 12)
      assert_match(/\A\*\*configuration\*\* `summer` of `AwesomeRobot::Compositions::TemperatureWatch`/, text)
      assert_includes text, 'Sets: `monitor: default, summer`'
      assert_match(%r{Declared at `models/compositions/temperature_watch.rb:\d+`}, text)
    end

    def test_a_section_nobody_declared_says_so
      text = File.read(@profile).sub("'default', 'forward'", "'default', 'sideways'")
      assert_equal '**configuration** `sideways` of `camera_gige::Task`: not declared',
                   query_at(query, @profile, "'sideways'", text: text, offset: 2)
    end

    def test_a_port_of_a_composition_child_with_the_model_that_declares_it
      drive = example('models/compositions/drive.rb')
      line = line_of(example('models/orogen/navigation.orogen'), "input_port 'pose'")
      assert_equal '**input port** `pose` of child `follower` (`navigation::PathFollower`): ' \
                   "`/base/samples/RigidBodyState`\n\nDeclared at `models/orogen/navigation.orogen:#{line}`",
                   hover('follower_child.pose_port', drive, offset: 16)
      assert_match(/\A\*\*output port\*\* `left_speed`/, hover('left_speed_port', drive))
      service = hover('position_child.position_samples_port', drive, offset: 20)
      assert_match(/\(`AwesomeRobot::Services::Position`\)/, service)
      assert_includes service, 'Declared at `models/services/position.rb:5`'
    end

    def test_the_cursor_on_nothing_known_shows_nothing
      assert_nil hover('robot do', offset: 1)
      assert_nil hover('# The robot as it is')
      assert_nil hover('.period(0.1)', offset: 2)
      assert_nil query.at(@profile, File.read(@profile), 1000, 0)
      assert_nil query.at(@profile, '', 0, 0)
    end

    def test_unknown_names_show_nothing
      text = "using_task_library 'nope'\nthrough 'nope' do\n  device(Devices::Nope, as: 'x')\n  nope_dev\nend\n"
      ["'nope'", "through 'nope'", 'Nope', 'nope_dev'].each do |needle|
        assert_nil query_at(query, @profile, needle, text: text, offset: needle.size - 2), needle
      end
    end

    def test_a_buffer_that_does_not_parse_uses_the_saved_file_s_modules
      text = File.read(@profile).sub(/^    end\n  end\nend\n\z/, '')
      refute_equal File.read(@profile), text
      assert_match(/device model/, query_at(query, @profile, 'F9, as:', text: text))
    end

    def test_a_file_that_failed_to_load_shows_what_was_declared_before_its_error
      app, path = app_with_broken_profile
      hover = LSP::Hover.new(app)
      assert_match(/\A\*\*device\*\* `imu`/, query_at(hover, path, "as: 'imu'", offset: 5))
      assert_nil query_at(hover, path, "as: 'nope'", offset: 5)
      assert_nil query_at(hover, path, 'Nope', offset: 1)
      assert_match(/device model/, query_at(hover, path, 'IMU', offset: 1))
    end

    def test_lines_ruby_warns_about_print_nothing
      text = File.read(@profile).sub("as: 'gps')", "as: 'gps').prefer_deployed_tasks(/gps]/)")
      assert_output('', '') { assert_match(/device model/, query_at(query, @profile, 'F9, as:', text: text)) }
    end

    # Rock's common_models keeps old names as autoloads of files that no
    # longer define them; once something tried one, it is listed among
    # the module's constants but has no value.
    def test_a_constant_whose_autoload_failed_is_nothing
      files = { 'models/services/ghost.rb' => "# defines nothing any more\n",
                'models/services/old.rb' => <<~RUBY }
                  module MyApp
                    autoload :Ghost, 'models/services/ghost'
                    begin
                      MyApp::Ghost
                    rescue NameError
                    end
                  end
                RUBY
      app = load_app(my_app(nil, files), problems: true, robots: [], everything: true, models: true)
      path = File.join(app.root, 'models/services/old.rb')
      hover = LSP::Hover.new(app)
      assert_nil query_at(hover, path, 'MyApp::Ghost', offset: 8)
      assert_match(/device model/, hover.at(path, 'MyApp::Devices::IMU', 0, 17))
    end

    def test_a_text_that_is_not_utf8_is_read_with_its_invalid_bytes_replaced
      text = "# caf\xE9\nx = '\xE9'; CommonModels::Devices::Bus::CAN\n".dup.force_encoding('UTF-8')
      refute text.valid_encoding?
      assert_nil query.at(@profile, text, 0, 5)
      assert_match(/bus model/, query.at(@profile, text, 1, text.lines[1].index('CAN') + 1))
      assert_empty LSP::Definition.new(example_app).at(@profile, text, 0, 5)
      assert_empty LSP::Completion.new(example_app).at(@profile, text, 0, 5)
      assert_kind_of Array, LSP::DocumentSymbols.new(example_app).of(@profile, text)
    end

    def test_positions_are_in_utf16_code_units
      text = "x = 'é𝄞'; CommonModels::Devices::Bus::CAN\n"
      # é is one unit (two bytes), 𝄞 two units (four bytes).
      assert_match(/bus model/, query.at(@profile, text, 0, text.index('CAN') + 1))
    end
  end
end
