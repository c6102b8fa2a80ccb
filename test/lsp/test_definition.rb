# frozen_string_literal: true

require_relative 'lsp_helper'

module Syskit
  # Go to definition: the locations the loaded app recorded.
  class TestLSPDefinition < Minitest::Test
    include SelfTest::LSPHelper

    def setup
      super
      @profile = example('models/profiles/live/base.rb')
    end

    def query
      @query ||= LSP::Definition.new(example_app)
    end

    # The definitions at +needle+ as [path relative to the gem, line].
    def definitions(needle, path = @profile, **position)
      query_at(query, path, needle, **position).map { |l| [l.path.delete_prefix("#{SelfTest::GEM_ROOT}/"), l.lineno] }
    end

    # +relative+ in syskit's own models, relative to the gem.
    def bundled(relative)
      File.join(App::BUNDLED_MODELS, relative).delete_prefix("#{SelfTest::GEM_ROOT}/")
    end

    def test_a_model_constant_goes_to_its_declaration
      f9 = 'examples/awesome_robot/models/devices/gps/ublox/f9.rb'
      assert_equal [[f9, line_of(f9, "device_type 'F9'")]], definitions('F9, as:')
      watch = 'examples/awesome_robot/models/compositions/temperature_watch.rb'
      assert_equal [[watch, line_of(watch, 'class TemperatureWatch')]], definitions('TemperatureWatch', offset: 1)
      assert_equal [[bundled('devices/bus/can.rb'), 10]], definitions('CAN, as:')
    end

    def test_a_task_library_goes_to_its_orogen_file_and_a_task_model_to_its_task
      assert_equal [[bundled('orogen/canbus.orogen'), 1]], definitions("'canbus'", offset: 2)
      assert_equal [[bundled('orogen/canbus.orogen'), 1]], definitions('canbus.Task)')
      assert_equal [[bundled('orogen/canbus.orogen'), 12]],
                   definitions('canbus.Task)', offset: 8)
    end

    def test_with_conf_goes_to_the_sections
      yml = 'examples/awesome_robot/config/orogen/camera_gige::Task.yml'
      assert_equal [[yml, line_of(yml, '--- name:forward')]], definitions("'forward')", offset: 2)
      assert_equal [[yml, 1], [yml, line_of(yml, '--- name:forward')]],
                   definitions("with_conf('default', 'forward')", offset: 3)
    end

    def test_with_conf_of_a_definition_goes_to_the_composition_s_configuration
      watch = 'examples/awesome_robot/models/compositions/temperature_watch.rb'
      assert_equal [[watch, line_of(watch, "conf 'summer'")]], definitions("with_conf('summer')", offset: 12)
    end

    def test_a_bus_name_and_a_device_action_go_to_their_statement
      profile = 'examples/awesome_robot/models/profiles/live/base.rb'
      assert_equal [[profile, line_of(@profile, "as: 'can0'")]], definitions("through 'can0'", offset: 10)
      assert_equal [[profile, line_of(@profile, "as: 'gps'")]], definitions('gps_dev')
      assert_equal [[profile, line_of(@profile, "define 'drive'")]], definitions("define 'drive'", offset: 9)
    end

    def test_a_deployment_goes_to_its_declaration
      orogen = 'examples/awesome_robot/models/orogen/camera_gige.orogen'
      assert_equal [[orogen, line_of(orogen, "deployment 'cameras'")]],
                   definitions("'cameras'", example('config/robots/default.rb'), offset: 2)
    end

    def test_a_port_of_a_child_goes_to_its_declaration
      drive = example('models/compositions/drive.rb')
      orogen = 'examples/awesome_robot/models/orogen/navigation.orogen'
      assert_equal [[orogen, line_of(orogen, "input_port 'pose'")]],
                   definitions('follower_child.pose_port', drive, offset: 16)
      service = 'examples/awesome_robot/models/services/position.rb'
      assert_equal [[service, line_of(service, "output_port 'position_samples'")]],
                   definitions('position_child.position_samples_port', drive, offset: 20)
    end

    def test_nothing_and_unknown_names_go_nowhere
      assert_empty definitions('robot do', offset: 1)
      assert_empty query.at(@profile, '', 0, 0)
      text = "using_task_library 'nope'\nthrough 'nope' do\n  Devices::Nope.with_conf('x')\nend\n"
      ["'nope'", "through 'nope'", 'Nope', 'with_conf'].each do |needle|
        assert_empty query_at(query, @profile, needle, text: text, offset: needle.size - 2), needle
      end
    end

    def test_a_file_that_failed_to_load_goes_to_what_was_declared_before_its_error
      app, path = app_with_broken_profile
      definition = LSP::Definition.new(app)
      assert_equal([[path, line_of(path, "as: 'imu'")]],
                   query_at(definition, path, "as: 'imu'", offset: 5).map { |l| [l.path, l.lineno] })
      assert_empty query_at(definition, path, "as: 'nope'", offset: 5)
      assert_empty query_at(definition, path, 'Nope', offset: 1)
    end
  end
end
