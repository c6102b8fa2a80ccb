# frozen_string_literal: true

require_relative 'generator_test_helper'

module Syskit
  # Network generation on small apps: bus ports, connections, policies,
  # configuration, deployment and order (SPEC 6, 7); the errors of each step
  # are in test_generator_errors.rb.
  class TestGenerator < Minitest::Test
    include GeneratorTestHelper

    def connections(plan)
      plan.connections.map { |c| ["#{c.from.task}.#{c.from.port}", "#{c.to.task}.#{c.to.port}", c.policy] }
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
             .sub("input_port('can_in', '/canbus/Message').needs_reliable_connection",
                  "input_port('can_in', '/canbus/Message')")
             .sub("output_port 'can_out'",
                  "input_port('other', '/double').needs_buffered_connection(50)\n  output_port 'can_out'")
      plan = generate(on_can0(a: '.period(0.01)'), 'models/orogen/sensor.orogen' => spec).plan
      assert_equal({ 'type' => 'data' }, plan.connections_to('a', 'can_in').first.policy)
      assert_equal({ 'type' => 'buffer', 'size' => 11 }, plan.connections_to('can0', 'wa').first.policy)
    end

    # Sections default and hot for sensor::Task, and configure methods that
    # record, in $configure_order, which ran when and what each one saw.
    RECORDED_CONFIGURE = {
      'config/orogen/sensor::Task.yml' => <<~YAML,
        --- name:default
        threshold: 2.5
        limits:
          name: low
          id: 1
        --- name:hot
        threshold: 40.0
        limits:
          mask: 3
      YAML
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
    }.freeze

    def test_configuration_sections_then_configure_methods_in_dependency_order
      plan = generate(on_can0(b: ".with_conf('default', 'hot')"), RECORDED_CONFIGURE).plan
      # rubocop:disable-next Style/GlobalVars -- the configure methods of RECORDED_CONFIGURE, run by the app, fill it
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
      yaml = "threshold: 7.5\n--- name:hot\nthreshold: 40.0\n"
      plan = generate(on_can0, 'config/orogen/sensor::Task.yml' => yaml).plan
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

    # The benchmark empties the CPU caches there, outside of the timings.
    def test_before_step_is_called_before_each_step_and_the_plan
      app = generate(on_can0).context.app
      calls = 0
      result = Network::Generator.plan_profile(app, MyApp::Profiles::Base.syskit_profile,
                                               before_step: -> { calls += 1 })
      assert_equal %w[instantiate merge buses deploy order configure connect plan], result.timings.keys
      assert_equal 8, calls
    end

    # The action of a device named 'a_dev' is 'a_dev_dev'; its name works too.
    def test_device_names_ending_in_dev
      robot = on_can0.sub("as: 'a'", "as: 'a_dev'")
      files = { 'config/robots/default.rb' => FILES['config/robots/default.rb'].sub("=> 'a'", "=> 'a_dev'") }
      plan = generate(robot.sub("prefer_deployed_tasks('a')", "prefer_deployed_tasks('a_dev')"), files).plan
      assert_equal %w[a_dev b can0], plan.tasks.map(&:name)
      profile = MyApp::Profiles::Base.syskit_profile
      assert_same profile.find_action('a_dev_dev'), profile.find_action('a_dev')
      assert_equal 'a_dev', MyApp::Profiles::Base.a_dev_dev.device.name
    end

    def test_a_subset_of_actions
      plan = generate("#{on_can0}device(Devices::IMU, as: 'imu')\n", actions: ['a_dev']).plan
      assert_equal %w[a can0], plan.tasks.map(&:name)
      assert_equal({ 'can_id' => [0x100, 0x7ff] }, plan.find_device('a').attributes)
    end

    def test_unknown_action
      errors = generation_error(on_can0, actions: ['c_dev'])
      assert_reported errors.first, /MyApp::Profiles::Base has no action 'c_dev'/,
                      at: 'models/profiles/base.rb:7', hint: /its actions are can0_dev, a_dev, b_dev/, root: @root
    end
  end
end
