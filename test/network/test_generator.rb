# frozen_string_literal: true

require 'helper'

module Syskit
  # Network generation on small apps: bus ports, connections, policies,
  # configuration, deployment, order, and the errors of each step (SPEC 6, 7).
  class TestGenerator < Minitest::Test
    # A demultiplexing bus driver (per-device ports both ways), a sensor
    # driver with one CAN port per direction, a writer-only driver.
    FILES = {
      'models/orogen/demux.orogen' => <<~RUBY,
        name 'demux'
        import_types_from 'canbus'
        task_context 'Task' do
          property 'devices', '/std/vector</canbus/Device>'
          dynamic_input_port(/^w\\w+$/, '/canbus/Message').needs_reliable_connection
          dynamic_output_port(/^\\w+$/, '/canbus/Message')
        end
      RUBY
      'models/orogen/demux.rb' => <<~RUBY,
        Syskit.extend_model OroGen.demux.Task do
          driver_for CommonModels::Devices::Bus::CAN, as: 'can'
        end
      RUBY
      'models/orogen/sensor.orogen' => <<~RUBY,
        name 'sensor'
        import_types_from 'canbus'
        task_context 'Task' do
          property 'threshold', 'double', 1.5
          property 'limits', '/canbus/Device'
          input_port('can_in', '/canbus/Message').needs_reliable_connection
          output_port 'can_out', '/canbus/Message'
          worstcase_processing_time 0.05
        end
      RUBY
      'models/orogen/sensor.rb' => <<~RUBY,
        require 'models/devices/imu'
        Syskit.extend_model OroGen.sensor.Task do
          driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'
        end
      RUBY
      'config/robots/default.rb' => <<~RUBY
        using_task_library 'demux'
        using_task_library 'sensor'
        using_task_library 'imu'
        Syskit.conf.use_deployment OroGen.demux.Task => 'can0'
        Syskit.conf.use_deployment OroGen.sensor.Task => 'a'
        Syskit.conf.use_deployment OroGen.sensor.Task => 'b'
        Syskit.conf.use_deployment OroGen.imu.Task => 'imu'
      RUBY
    }.freeze

    LIBS = %w[demux sensor imu].freeze

    def generate(robot, files = {}, libraries: LIBS, actions: [], **more_files)
      root = my_app(robot, FILES.merge(files).merge(more_files), libraries: libraries)
      @root = root
      app = load_app(root)
      Network::Generator.plan_profile(app, MyApp::Profiles::Base.syskit_profile, actions: actions)
    end

    def generation_error(robot, files = {}, **options)
      error = assert_raises(Syskit::Error) { generate(robot, files, **options) }
      error.is_a?(ErrorList) ? error.errors : [error]
    end

    def connections(plan)
      plan.connections.map { |c| ["#{c.from.task}.#{c.from.port}", "#{c.to.task}.#{c.to.port}", c.policy] }
    end

    ON_CAN0 = <<~RUBY
      com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
      through 'can0' do
        device(Devices::TemperatureSensor, as: 'a').can_id(0x100, 0x7ff).prefer_deployed_tasks('a')%<a>s
        device(Devices::TemperatureSensor, as: 'b'%<b_opts>s).can_id(0x200, 0x7ff).prefer_deployed_tasks('b')%<b>s
      end
    RUBY

    def on_can0(a: '', b: '', b_opts: '')
      format(ON_CAN0, a: a, b: b, b_opts: b_opts)
    end

    def test_demultiplexing_bus_gets_device_and_w_device_ports
      plan = generate(on_can0).plan
      ports = plan.find_task('can0').ports.map { |p| [p.name, p.direction, p.dynamic] }
      assert_equal [['a', 'output', true], ['b', 'output', true], ['wa', 'input', true], ['wb', 'input', true]], ports
      assert_equal [['a.can_out', 'can0.wa', { 'type' => 'buffer', 'size' => 20 }],
                    ['b.can_out', 'can0.wb', { 'type' => 'buffer', 'size' => 20 }],
                    ['can0.a', 'a.can_in', { 'type' => 'buffer', 'size' => 20 }],
                    ['can0.b', 'b.can_in', { 'type' => 'buffer', 'size' => 20 }]], connections(plan)
    end

    def test_one_way_devices_get_only_their_direction
      plan = generate(on_can0(b_opts: ', client_to_bus: false')).plan
      assert_equal %w[a b wa], plan.find_task('can0').ports.map(&:name)
      plan = nil
      @loaded_apps.pop.unload
      plan = generate(on_can0(b_opts: ', bus_to_client: false')).plan
      assert_equal %w[a wa wb], plan.find_task('can0').ports.map(&:name)
      assert_empty plan.connections_to('b')
    end

    def test_buffer_size_derives_from_the_writer_period_and_burst_and_the_reader_processing_time
      plan = generate(on_can0(a: '.period(0.01).burst(3)', b: '.burst(4)')).plan
      policies = connections(plan).to_h { |from, to, policy| ["#{from}->#{to}", policy] }
      # into the bus (no worstcase_processing_time on demux::Task): 3 + 0.1/0.01
      assert_equal({ 'type' => 'buffer', 'size' => 13 }, policies['a.can_out->can0.wa'])
      # into sensor::Task (worstcase_processing_time 0.05): 3 + 0.05/0.01
      assert_equal({ 'type' => 'buffer', 'size' => 8 }, policies['can0.a->a.can_in'])
      # burst without period: burst + 19
      assert_equal({ 'type' => 'buffer', 'size' => 23 }, policies['b.can_out->can0.wb'])
    end

    def test_a_sink_that_is_not_reliable_gets_a_data_policy_and_buffered_connection_is_a_minimum
      spec = FILES['models/orogen/sensor.orogen']
             .sub("input_port('can_in', '/canbus/Message').needs_reliable_connection", "input_port('can_in', '/canbus/Message')")
             .sub("output_port 'can_out'", "input_port('other', '/double').needs_buffered_connection(50)\n  output_port 'can_out'")
      plan = generate(on_can0(a: '.period(0.01)'), 'models/orogen/sensor.orogen' => spec).plan
      assert_equal({ 'type' => 'data' }, plan.connections_to('a', 'can_in').first.policy)
      assert_equal({ 'type' => 'buffer', 'size' => 11 }, plan.connections_to('can0', 'wa').first.policy)
    end

    def test_configuration_sections_then_configure_methods_in_dependency_order
      files = {
        'config/orogen/sensor::Task.yml' => "--- name:default\nthreshold: 2.5\nlimits:\n  name: low\n  id: 1\n--- name:hot\nthreshold: 40.0\nlimits:\n  mask: 3\n",
        'models/orogen/sensor.rb' => <<~RUBY
          require 'models/devices/imu'
          $configure_order = []
          Syskit.extend_model OroGen.sensor.Task do
            driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'
            def configure
              super
              $configure_order << [sensor_dev.name, properties.threshold, each_child.map { |c, _| c.name }]
            end
          end
          Syskit.extend_model OroGen.demux.Task do
            def configure
              super
              $configure_order << [can_dev.name, each_declared_attached_device.map(&:name)]
            end
          end
        RUBY
      }
      plan = generate(on_can0(b: ".with_conf('default', 'hot')"), files).plan
      assert_equal [['can0', %w[a b]], ['a', 2.5, ['can0']], ['b', 40.0, ['can0']]], $configure_order
      assert_equal({ 'name' => 'low', 'id' => 1, 'mask' => 0 }, plan.find_task('a').properties['limits'])
      assert_equal({ 'name' => 'low', 'id' => 1, 'mask' => 3 }, plan.find_task('b').properties['limits'],
                   'hashes are merged key by key')
      assert_equal %w[default hot], plan.find_task('b').conf
      assert_equal(['configure can0', 'start can0', 'configure a', 'configure b', 'start a', 'start b'],
                   plan.order.map { |s| "#{s.step} #{s.task}" })
    ensure
      $configure_order = nil # rubocop:disable Style/GlobalVars
    end

    def test_a_file_without_header_starts_with_the_default_section
      plan = generate(on_can0, 'config/orogen/sensor::Task.yml' => "threshold: 7.5\n--- name:hot\nthreshold: 40.0\n").plan
      assert_equal 7.5, plan.find_task('a').properties['threshold']
    end

    def test_robot_device_and_requirements_with_another_configuration
      files = {
        'config/orogen/sensor::Task.yml' => "--- name:default\n--- name:hot\nthreshold: 40.0\n",
        'models/orogen/sensor.rb' => <<~RUBY
          require 'models/devices/imu'
          Syskit.extend_model OroGen.sensor.Task do
            driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'
            def configure
              super
              raise 'robot_device is not the sensor' unless robot_device.equal?(sensor_dev)
            end
          end
        RUBY
      }
      root = my_app(on_can0, FILES.merge(files), libraries: LIBS)
      app = load_app(root)
      hot = MyApp::Profiles::Base.a_dev.with_conf('default', 'hot')
      result = Network::Generator.new(app, [hot], robot_config: app.robot_config).generate
      assert_equal 40.0, result.plan.find_task('a').properties['threshold']
      assert_equal ['default'], MyApp::Profiles::Base.a_dev.conf, 'with_conf on an action returns a copy'
      assert_same MyApp::Profiles::Base.a_dev, MyApp::Profiles::Base.a_dev
    end

    def test_a_subset_of_actions
      plan = generate(on_can0 + "device(Devices::IMU, as: 'imu')\n", actions: ['a_dev']).plan
      assert_equal %w[a can0], plan.tasks.map(&:name)
      assert_equal({ 'can_id' => [0x100, 0x7ff] }, plan.find_device('a').attributes)
    end

    def test_unknown_action
      errors = generation_error(on_can0, actions: ['c_dev'])
      assert_reported errors.first, /MyApp::Profiles::Base has no action 'c_dev'/, at: 'models/profiles/base.rb:7',
                                                                                   hint: /its actions are can0_dev, a_dev, b_dev/, root: @root
    end

    # --- errors of each step -----------------------------------------------

    def test_device_and_w_device_names_clash_on_one_bus
      robot = "com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\nthrough 'can0' do\n  " \
              "device(Devices::TemperatureSensor, as: 'a').can_id(1).prefer_deployed_tasks('a')\n  " \
              "device(Devices::TemperatureSensor, as: 'wa').can_id(2).prefer_deployed_tasks('b')\nend\n"
      errors = generation_error(robot)
      assert_reported errors.first, %r{device 'a' and device 'wa' both need a port named 'wa' on demux::Task \(input for a, output for wa; device 'a' is declared at models/profiles/base.rb:11\)},
                      at: 'models/profiles/base.rb:12', hint: /rename one of them/, root: @root
    end

    def test_device_name_clashes_with_a_static_port_of_the_bus_driver
      robot = "com_bus CommonModels::Devices::Bus::CAN, as: 'can0', using: OroGen.canbus.Task\nthrough 'can0' do\n  " \
              "device(Devices::TemperatureSensor, as: 'in').can_id(1)\nend\n"
      errors = generation_error(robot, { 'config/robots/default.rb' => "using_task_library 'sensor'\nSyskit.conf.use_deployment 'test_canbus'\nSyskit.conf.use_deployment OroGen.sensor.Task => 'in'\n" },
                                libraries: %w[demux sensor canbus])
      assert_reported errors.first, /device 'in''s output port 'in' on canbus::Task collides with its input port 'in'/,
                      at: 'models/profiles/base.rb:11', hint: /rename the device/, root: @root
    end

    def test_device_driver_without_a_port_of_the_bus_type
      robot = "com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\nthrough 'can0' do\n  device(Devices::IMU, as: 'imu').can_id(1)\nend\n"
      errors = generation_error(robot)
      assert_reported errors.first, %r{imu::Task, the driver of device 'imu', has no input port of type /canbus/Message to receive frames from bus 'can0'},
                      at: 'models/profiles/base.rb:11', hint: /declare the device with bus_to_client: false if it does not receive frames from the bus/, root: @root
    end

    def test_device_driver_with_several_ports_of_the_bus_type
      spec = FILES['models/orogen/sensor.orogen'].sub("output_port 'can_out'", "input_port 'diag_in', '/canbus/Message'\n  output_port 'can_out'")
      errors = generation_error(on_can0, 'models/orogen/sensor.orogen' => spec)
      assert_reported errors.first, %r{sensor::Task, the driver of device 'a', has several input ports of type /canbus/Message: can_in, diag_in},
                      at: 'models/profiles/base.rb:11',
                      hint: /provides CommonModels::Devices::Bus::CAN::ClientInSrv, as: 'bus_client', 'from_bus' => 'can_in' .* pass bus_to_client: 'bus_client'/, root: @root
    end

    def test_unknown_client_service_name
      errors = generation_error(on_can0(b_opts: ", bus_to_client: 'client'"))
      assert_reported errors.first, /bus_to_client: 'client' names no CommonModels::Devices::Bus::CAN::ClientInSrv service of sensor::Task/,
                      at: 'models/profiles/base.rb:12', hint: /provides CommonModels::Devices::Bus::CAN::ClientInSrv, as: 'client'/, root: @root
    end

    def test_two_writers_into_an_input_that_does_not_multiplex
      files = { 'models/orogen/demux.orogen' => "name 'demux'\nimport_types_from 'canbus'\ntask_context 'Task' do\n  input_port 'in', '/canbus/Message'\n  dynamic_output_port(/^\\w+$/, '/canbus/Message')\nend\n" }
      errors = generation_error(on_can0, files)
      assert_reported errors.first, /demux::Task 'can0''s input port 'in' does not multiplex but 2 outputs write to it: a.can_out \(device 'a'\), b.can_out \(device 'b'\)/,
                      at: 'models/profiles/base.rb:12', hint: /mark it .multiplexes/, root: @root
    end

    def test_bus_driver_without_any_port_for_a_device
      files = { 'models/orogen/demux.orogen' => "name 'demux'\nimport_types_from 'canbus'\ntask_context 'Task' do\n  dynamic_output_port(/^\\w+$/, '/canbus/Message')\nend\n" }
      errors = generation_error(on_can0, files)
      assert_reported errors.first, /demux::Task, the driver of bus 'can0', has no way to receive device 'a''s frames/,
                      at: 'models/profiles/base.rb:11', hint: %r{dynamic_input_port\(/\^\\w\+\$/, '/canbus/Message'\)}, root: @root
    end

    def test_no_deployment
      errors = generation_error("device(Devices::IMU, as: 'imu')\n", 'config/robots/default.rb' => "# nothing\n")
      assert_reported errors.first, /no deployed task can run imu::Task, the driver of device 'imu', on robot 'default'/,
                      at: 'models/profiles/base.rb:9', hint: %r{add to config/robots/default.rb: Syskit.conf.use_deployment OroGen.imu.Task => 'imu'}, root: @root
    end

    def test_several_deployments_without_preference
      errors = generation_error(on_can0.sub(".prefer_deployed_tasks('a')", ''))
      assert_reported errors.first, /several deployed tasks can run device 'a''s driver sensor::Task: a \(sensor::Task, deployment a\), b \(sensor::Task, deployment b\)/,
                      at: 'models/profiles/base.rb:11', hint: /\.prefer_deployed_tasks\('a'\)/, root: @root
    end

    def test_preference_matching_nothing
      errors = generation_error(on_can0.sub(".prefer_deployed_tasks('a')", '.prefer_deployed_tasks(/front/)'))
      assert_reported errors.first, %r{none of the deployed tasks that can run device 'a''s driver sensor::Task matches prefer_deployed_tasks\(/front/\)},
                      at: 'models/profiles/base.rb:11', root: @root
    end

    def test_two_devices_wanting_one_deployed_task
      errors = generation_error(on_can0.sub(".prefer_deployed_tasks('b')", ".prefer_deployed_tasks('a')"))
      assert_reported errors.first, /device 'a' and device 'b' both need the deployed task a \(sensor::Task, deployment a\)/,
                      at: 'models/profiles/base.rb:12', hint: %r{prefer_deployed_tasks\(/b/\)}, root: @root
    end

    def conf_error(yaml, conf: '')
      errors = generation_error(on_can0(b: conf), 'config/orogen/sensor::Task.yml' => yaml)
      errors.first
    end

    def test_unknown_section
      error = conf_error("--- name:default\nthreshold: 1.0\n--- name:cold\nthreshold: -10.0\n", conf: ".with_conf('hot')")
      assert_reported error, /no section 'hot' in sensor::Task.yml \(sections: default, cold\)/, at: 'models/profiles/base.rb:12',
                                                                                                 hint: /with_conf replaces \['default'\], so write with_conf\('default', 'hot'\)/, root: @root
    end

    def test_section_declared_twice
      error = conf_error("--- name:default\nthreshold: 1.0\n--- name:default\nthreshold: 2.0\n")
      assert_reported error, /section 'default' is declared twice \(first at line 1\)/, at: 'config/orogen/sensor::Task.yml:3', root: @root
    end

    def test_unknown_property_in_a_section
      error = conf_error("--- name:default\nthreshold: 1.0\nthreshhold: 2.0\n")
      assert_reported error, /sensor::Task has no property 'threshhold' \(did you mean 'threshold'\?\)/,
                      at: 'config/orogen/sensor::Task.yml:3', hint: /its properties are limits, threshold/, root: @root
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
      assert_reported error, /a configuration section must map property names to values/, at: 'config/orogen/sensor::Task.yml:2', root: @root
    end

    def test_sections_asked_for_a_task_without_configuration_file
      errors = generation_error(on_can0(b: ".with_conf('default', 'hot')"))
      assert_reported errors.first, /device 'b' asks for sections default, hot but sensor::Task has no configuration file/,
                      at: 'models/profiles/base.rb:12', hint: %r{create config/orogen/sensor::Task.yml with a '--- name:hot' section}, root: @root
    end

    def configure_error(body, extra = '')
      ext = "require 'models/devices/imu'\nSyskit.extend_model OroGen.sensor.Task do\n  driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'\n#{extra}  def configure\n    super\n#{body}  end\nend\n"
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
      assert_reported error, /in sensor::Task's configure for device 'a': sensor::Task has no property 'threshhold' \(did you mean 'threshold'\?\)/,
                      at: 'models/orogen/sensor.rb:6', hint: /its properties are limits, threshold/, root: @root
    end

    def test_a_wrong_value_in_a_configure_method
      error = configure_error("    properties.threshold = 'x'\n")
      assert_reported error, /property 'threshold' of sensor::Task: expected a number/, at: 'models/orogen/sensor.rb:6', root: @root
    end

    def stub_error(stub)
      ext = "Syskit.extend_model OroGen.demux.Task do\n  driver_for CommonModels::Devices::Bus::CAN, as: 'can'\n  stub do\n#{stub}  end\nend\n"
      generation_error(on_can0, 'models/orogen/demux.rb' => ext).first
    end

    def test_a_stub_creating_a_port_that_matches_no_pattern
      error = stub_error("    create_output_port 'a b', '/canbus/Message'\n")
      assert_reported error, %r{demux::Task cannot create output port 'a b' \(/canbus/Message\): its patterns are dynamic output port /\^\\w\+\$/},
                      at: 'models/orogen/demux.rb:4', root: @root
    end

    def test_a_stub_that_does_not_create_the_port_a_device_needs
      error = stub_error("    create_output_port 'a', '/canbus/Message'\n")
      assert_reported error, /demux::Task's configure and stub did not create the input port 'wa' that device 'a' needs \(created: a\)/,
                      at: 'models/orogen/demux.rb:3', hint: /a port per attached device/, root: @root
    end

    def test_errors_of_a_step_are_all_reported
      errors = generation_error(on_can0.gsub(/\.prefer_deployed_tasks\('\w'\)/, ''))
      assert_equal 2, errors.size
      assert_equal(%w[models/profiles/base.rb:11 models/profiles/base.rb:12], errors.map { |e| e.location.to_s(@root) })
    end
  end
end
