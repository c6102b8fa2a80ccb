# frozen_string_literal: true

require_relative 'generator_test_helper'

module Syskit
  # The errors of each step of network generation, each at the line the
  # user must change (SPEC 6, 7).
  class TestGeneratorErrors < Minitest::Test
    include GeneratorTestHelper

    def test_device_and_w_device_names_clash_on_one_bus
      robot = "com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\nthrough 'can0' do\n  " \
              "device(Devices::TemperatureSensor, as: 'a').can_id(1).prefer_deployed_tasks('a')\n  " \
              "device(Devices::TemperatureSensor, as: 'wa').can_id(2).prefer_deployed_tasks('b')\nend\n"
      errors = generation_error(robot)
      assert_reported errors.first,
                      Regexp.new('device \'a\' and device \'wa\' both need a port named \'wa\' on demux::Task ' \
                                 '\(input for a, output for wa; ' \
                                 'device \'a\' is declared at models/profiles/base.rb:11\)'),
                      at: 'models/profiles/base.rb:12', hint: /rename one of them/, root: @root
    end

    def test_device_name_clashes_with_a_static_port_of_the_bus_driver
      robot = "com_bus CommonModels::Devices::Bus::CAN, as: 'can0', using: OroGen.canbus.Task\nthrough 'can0' do\n  " \
              "device(Devices::TemperatureSensor, as: 'in').can_id(1)\nend\n"
      config = <<~RUBY
        using_task_library 'sensor'
        Syskit.conf.use_deployment 'test_canbus'
        Syskit.conf.use_deployment OroGen.sensor.Task => 'in'
      RUBY
      errors = generation_error(robot, { 'config/robots/default.rb' => config }, libraries: %w[demux sensor canbus])
      assert_reported errors.first,
                      /the output port 'in' of device 'in' on canbus::Task collides with its input port 'in'/,
                      at: 'models/profiles/base.rb:11', hint: /rename the device/, root: @root
    end

    def test_device_driver_without_a_port_of_the_bus_type
      robot = <<~RUBY
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through 'can0' do
          device(Devices::IMU, as: 'imu').can_id(1)
        end
      RUBY
      errors = generation_error(robot)
      assert_reported errors.first,
                      Regexp.new('imu::Task, the driver of device \'imu\', has no input port of type /canbus/Message ' \
                                 'to receive frames from bus \'can0\''),
                      at: 'models/profiles/base.rb:11',
                      hint: /declare the device with bus_to_client: false if it does not receive frames from the bus/,
                      root: @root
    end

    def test_device_driver_with_several_ports_of_the_bus_type
      spec = FILES['models/orogen/sensor.orogen']
             .sub("output_port 'can_out'", "input_port 'diag_in', '/canbus/Message'\n  output_port 'can_out'")
      errors = generation_error(on_can0, 'models/orogen/sensor.orogen' => spec)
      assert_reported errors.first,
                      Regexp.new('sensor::Task, the driver of device \'a\', has several input ports of type ' \
                                 '/canbus/Message: can_in, diag_in'),
                      at: 'models/profiles/base.rb:11',
                      hint: Regexp.new('provides CommonModels::Devices::Bus::CAN::ClientInSrv, as: \'bus_client\', ' \
                                       '\'from_bus\' => \'can_in\' .* pass bus_to_client: \'bus_client\''),
                      root: @root
    end

    def test_unknown_client_service_name
      errors = generation_error(on_can0(b_opts: ", bus_to_client: 'client'"))
      assert_reported errors.first,
                      Regexp.new('bus_to_client: \'client\' names no CommonModels::Devices::Bus::CAN::ClientInSrv ' \
                                 'service of sensor::Task'),
                      at: 'models/profiles/base.rb:12',
                      hint: /provides CommonModels::Devices::Bus::CAN::ClientInSrv, as: 'client'/, root: @root
    end

    def test_two_writers_into_an_input_that_does_not_multiplex
      files = { 'models/orogen/demux.orogen' => <<~RUBY }
        name 'demux'
        import_types_from 'canbus'
        task_context 'Task' do
          input_port 'in', '/canbus/Message'
          dynamic_output_port(/^\\w+$/, '/canbus/Message')
        end
      RUBY
      errors = generation_error(on_can0, files)
      assert_reported errors.first,
                      Regexp.new('demux::Task \'can0\'\'s input port \'in\' does not multiplex ' \
                                 'but 2 outputs write to it: a.can_out \(device \'a\'\), b.can_out \(device \'b\'\)'),
                      at: 'models/profiles/base.rb:12', hint: /mark it .multiplexes/, root: @root
    end

    def test_bus_driver_without_any_port_for_a_device
      files = { 'models/orogen/demux.orogen' => <<~RUBY }
        name 'demux'
        import_types_from 'canbus'
        task_context 'Task' do
          dynamic_output_port(/^\\w+$/, '/canbus/Message')
        end
      RUBY
      errors = generation_error(on_can0, files)
      assert_reported errors.first,
                      /demux::Task, the driver of bus 'can0', has no way to receive the frames of device 'a'/,
                      at: 'models/profiles/base.rb:11',
                      hint: %r{dynamic_input_port\(/\^\\w\+\$/, '/canbus/Message'\)}, root: @root
    end

    def test_no_deployment
      errors = generation_error("device(Devices::IMU, as: 'imu')\n", 'config/robots/default.rb' => "# nothing\n")
      assert_reported errors.first,
                      /no deployed task can run imu::Task, the driver of device 'imu', on robot 'default'/,
                      at: 'models/profiles/base.rb:9',
                      hint: %r{add to config/robots/default.rb: Syskit.conf.use_deployment OroGen.imu.Task => 'imu'},
                      root: @root
    end

    def test_several_deployments_without_preference
      errors = generation_error(on_can0.sub(".prefer_deployed_tasks('a')", ''))
      assert_reported errors.first,
                      Regexp.new('several deployed tasks can run the driver of device \'a\' \\(sensor::Task\\): ' \
                                 'a \(sensor::Task, deployment a\), b \(sensor::Task, deployment b\)'),
                      at: 'models/profiles/base.rb:11', hint: /\.prefer_deployed_tasks\('a'\)/, root: @root
    end

    # Each device without a preference is told of the candidates: the
    # first ten and how many more, or n errors would list n candidates.
    def test_candidate_lists_stay_short
      devices = Array.new(12) { |i| "  device(Devices::TemperatureSensor, as: 'd#{i}').can_id(#{0x100 + i}, 0x7ff)" }
      deployments = Array.new(12) { |i| "Syskit.conf.use_deployment OroGen.sensor.Task => 'd#{i}'" }
      robot = "com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\nthrough 'can0' do\n#{devices.join("\n")}\nend\n"
      config = "#{FILES['config/robots/default.rb']}#{deployments.join("\n")}\n"
      errors = generation_error(robot, 'config/robots/default.rb' => config)
      assert_equal 12, errors.size
      assert_match(/\(sensor::Task\): a \(sensor::Task, deployment a\), b \(.*\), d0 .*, d5 \(.*\) and 4 more\z/,
                   errors.first.message)
      assert_match(/prefer_deployed_tasks\('d0'\)/, errors.first.hint)
    end

    def test_preference_matching_nothing
      errors = generation_error(on_can0.sub(".prefer_deployed_tasks('a')", '.prefer_deployed_tasks(/front/)'))
      assert_reported errors.first,
                      Regexp.new('no deployed task that can run the driver of device \'a\' \\(sensor::Task\\) ' \
                                 'matches prefer_deployed_tasks\(/front/\)'),
                      at: 'models/profiles/base.rb:11', root: @root
    end

    def test_two_devices_wanting_one_deployed_task
      errors = generation_error(on_can0.sub(".prefer_deployed_tasks('b')", ".prefer_deployed_tasks('a')"))
      assert_reported errors.first,
                      /device 'a' and device 'b' both need the deployed task a \(sensor::Task, deployment a\)/,
                      at: 'models/profiles/base.rb:12', hint: %r{prefer_deployed_tasks\(/b/\)}, root: @root
    end

    def conf_error(yaml, conf: '')
      errors = generation_error(on_can0(b: conf), 'config/orogen/sensor::Task.yml' => yaml)
      errors.first
    end

    def test_unknown_section
      error = conf_error("--- name:default\nthreshold: 1.0\n--- name:cold\nthreshold: -10.0\n",
                         conf: ".with_conf('hot')")
      assert_reported error, /no section 'hot' in sensor::Task.yml \(sections: default, cold\)/,
                      at: 'models/profiles/base.rb:12',
                      hint: /with_conf replaces \['default'\], so write with_conf\('default', 'hot'\)/, root: @root
    end

    def test_section_declared_twice
      error = conf_error("--- name:default\nthreshold: 1.0\n--- name:default\nthreshold: 2.0\n")
      assert_reported error, /section 'default' is declared twice \(first at line 1\)/,
                      at: 'config/orogen/sensor::Task.yml:3', root: @root
    end

    def test_unknown_property_in_a_section
      error = conf_error("--- name:default\nthreshold: 1.0\n--- name:hot\nthreshhold: 2.0\n",
                         conf: ".with_conf('default', 'hot')")
      assert_reported error, Regexp.new("sensor::Task has no property 'threshhold' \\(did you mean 'threshold'\\?\\) " \
                                        "\\(section 'hot' of sensor::Task.yml\\)"),
                      at: 'config/orogen/sensor::Task.yml:4', hint: /its properties are limits, threshold/, root: @root
    end

    def test_value_of_the_wrong_type
      error = conf_error("--- name:default\nthreshold: high\n")
      assert_reported error, %r{property 'threshold' of sensor::Task: expected a number for /double, got "high"},
                      at: 'config/orogen/sensor::Task.yml:2', root: @root
    end

    def test_invalid_yaml
      error = conf_error("--- name:default\nthreshold: [1\n")
      assert_reported error, /invalid YAML/, at: 'config/orogen/sensor::Task.yml:2', root: @root
    end

    def test_ruby_objects_and_aliases_are_refused
      error = conf_error("--- name:default\nthreshold: !ruby/object:OpenStruct {}\n")
      assert_reported error, %r{YAML tags such as !ruby/object:OpenStruct are not allowed in configuration files},
                      at: 'config/orogen/sensor::Task.yml:2', hint: /plain data: no tags, no Ruby objects/, root: @root
      @loaded_apps.pop.unload
      error = conf_error("--- name:default\nlimits: &l\n  id: 1\nother: *l\n")
      assert_reported error, /YAML aliases are not allowed/, at: 'config/orogen/sensor::Task.yml:4', root: @root
    end

    def test_a_section_that_is_not_a_mapping
      error = conf_error("--- name:default\n- 1\n- 2\n")
      assert_reported error, /a configuration section must map property names to values/,
                      at: 'config/orogen/sensor::Task.yml:2', root: @root
    end

    def test_sections_asked_for_a_task_without_configuration_file
      errors = generation_error(on_can0(b: ".with_conf('default', 'hot')"))
      assert_reported errors.first,
                      /device 'b' asks for sections default, hot but sensor::Task has no configuration file/,
                      at: 'models/profiles/base.rb:12',
                      hint: %r{create config/orogen/sensor::Task.yml with a '--- name:hot' section}, root: @root
    end

    def configure_error(body, extra = '')
      ext = "require 'models/devices/imu'\nSyskit.extend_model OroGen.sensor.Task do\n  " \
            "driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'\n" \
            "#{extra}  def configure\n    super\n#{body}  end\nend\n"
      generation_error(on_can0, 'models/orogen/sensor.rb' => ext).first
    end

    def test_an_exception_in_a_configure_method
      error = configure_error("    raise ArgumentError, 'bad calibration' if sensor_dev.name == 'b'\n")
      assert_reported error, /in sensor::Task's configure for device 'b': ArgumentError: bad calibration/,
                      at: 'models/orogen/sensor.rb:6', root: @root
      assert_kind_of ConfigureMethodError, error
    end

    def test_a_misspelled_property_in_a_configure_method
      error = configure_error("    properties.threshhold = 2\n")
      assert_reported error,
                      Regexp.new('in sensor::Task\'s configure for device \'a\': ' \
                                 'sensor::Task has no property \'threshhold\' \(did you mean \'threshold\'\?\)'),
                      at: 'models/orogen/sensor.rb:6', hint: /its properties are limits, threshold/, root: @root
    end

    def test_a_wrong_value_in_a_configure_method
      error = configure_error("    properties.threshold = 'x'\n")
      assert_reported error, /property 'threshold' of sensor::Task: expected a number/,
                      at: 'models/orogen/sensor.rb:6', root: @root
    end

    def stub_error(stub)
      ext = "Syskit.extend_model OroGen.demux.Task do\n  " \
            "driver_for CommonModels::Devices::Bus::CAN, as: 'can'\n  stub do\n#{stub}  end\nend\n"
      generation_error(on_can0, 'models/orogen/demux.rb' => ext).first
    end

    def test_a_stub_creating_a_port_that_matches_no_pattern
      error = stub_error("    create_output_port 'a b', '/canbus/Message'\n")
      assert_reported error,
                      Regexp.new('demux::Task cannot create output port \'a b\' \(/canbus/Message\): ' \
                                 'its patterns are dynamic output port /\^\\\\w\+\$/'),
                      at: 'models/orogen/demux.rb:4', root: @root
    end

    def test_a_stub_that_does_not_create_the_port_a_device_needs
      error = stub_error("    create_output_port 'a', '/canbus/Message'\n")
      assert_reported error,
                      Regexp.new('demux::Task\'s configure and stub did not create the input port \'wa\' ' \
                                 'that device \'a\' needs \(created: a\)'),
                      at: 'models/orogen/demux.rb:3', hint: /a port per attached device/, root: @root
    end

    def test_errors_of_a_step_are_all_reported
      errors = generation_error(on_can0.gsub(/\.prefer_deployed_tasks\('\w'\)/, ''))
      assert_equal 2, errors.size
      assert_equal(%w[models/profiles/base.rb:11 models/profiles/base.rb:12], errors.map { |e| e.location.to_s(@root) })
    end
  end
end
