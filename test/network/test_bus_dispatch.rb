# frozen_string_literal: true

require_relative 'generator_test_helper'

module Syskit
  # How a bus driver serves the devices of its bus, as Syskit's bus tests
  # describe it: one per-device service for every device declared on the
  # bus whenever the bus is in the network (input only / output only for
  # one-way devices), unless the bus model dispatches lazily; and how
  # sample_size and override_policy weigh on the bus connections.
  class TestBusDispatch < Minitest::Test
    include GeneratorTestHelper

    def bus_ports(result)
      result.plan.find_task('can0').ports.map(&:name)
    end

    def attached(result)
      result.tasks.find { |t| t.name == 'can0' }.each_attached_device.map(&:name)
    end

    def test_a_bus_planned_alone_serves_every_device_declared_on_it
      result = generate(on_can0, actions: %w[can0_dev])
      assert_equal %w[can0], result.plan.tasks.map(&:name)
      assert_equal %w[a b wa wb], bus_ports(result)
      assert_empty result.plan.connections
      assert_equal %w[a b], attached(result)
    end

    def test_the_ports_of_one_way_devices_are_those_of_their_direction
      robot = on_can0(b_opts: ', bus_to_client: false').sub("as: 'a'", "as: 'a', client_to_bus: false")
      assert_equal %w[a wb], bus_ports(generate(robot, actions: %w[can0_dev]))
    end

    def test_a_device_planned_alone_leaves_the_other_devices_served
      result = generate(on_can0, actions: %w[a_dev])
      assert_equal %w[a can0], result.plan.tasks.map(&:name)
      assert_equal %w[a b wa wb], bus_ports(result)
      links = result.plan.connections.map { |c| [c.from.task, c.to.task] }
      assert_equal [%w[a can0], %w[can0 a]], links
    end

    LAZY_BUS = {
      'models/devices/lazy_can.rb' => <<~RUBY,
        module MyApp
          module Devices
            com_bus_type 'LazyCAN', lazy_dispatch: true do
              provides CommonModels::Devices::Bus::CAN
            end
          end
        end
      RUBY
      'models/orogen/demux.rb' => <<~RUBY
        require 'models/devices/lazy_can'
        Syskit.extend_model OroGen.demux.Task do
          driver_for MyApp::Devices::LazyCAN, as: 'can'
        end
      RUBY
    }.freeze

    def lazy_can0
      on_can0.sub('CommonModels::Devices::Bus::CAN', 'Devices::LazyCAN')
    end

    def test_a_lazy_bus_serves_only_the_devices_in_the_network
      result = generate(lazy_can0, LAZY_BUS, actions: %w[can0_dev])
      assert_empty bus_ports(result)
      assert_empty attached(result)
      @loaded_apps.pop.unload
      result = generate(lazy_can0, LAZY_BUS, actions: %w[b_dev])
      assert_equal %w[b wb], bus_ports(result)
      assert_equal %w[b], attached(result)
    end

    # A bus driver with per-device outputs but a single input.
    ONE_INPUT = <<~RUBY
      name 'demux'
      import_types_from 'canbus'
      task_context 'Task' do
        input_port('in', '/canbus/Message')
        input_port('spare', '/canbus/Message')
        dynamic_output_port(/^\\w+$/, '/canbus/Message')
      end
    RUBY

    def test_a_declared_device_the_bus_driver_cannot_serve_is_an_error_even_when_not_planned
      robot = on_can0(b_opts: ', client_to_bus: false')
      errors = generation_error(robot, { 'models/orogen/demux.orogen' => ONE_INPUT }, actions: %w[b_dev])
      assert_equal 1, errors.size
      assert_reported errors.first,
                      /demux::Task, the driver of bus 'can0', has no way to receive the frames of device 'a'/,
                      at: 'models/profiles/base.rb:11', root: @root
    end

    def policies(plan)
      plan.connections.to_h { |c| ["#{c.from.task}.#{c.from.port}", c.policy['size'] || c.policy['type']] }
    end

    def test_sample_size_multiplies_the_buffers_from_the_bus_to_the_device
      plan = generate(on_can0(a: '.period(0.01).burst(2).sample_size(4)', b: '.sample_size(3)')).plan
      sizes = policies(plan)
      # sensor::Task reads within 0.05 s: 4 messages per sample * (2 + 0.05 / 0.01) samples
      assert_equal 28, sizes['can0.a']
      # no period: 3 * (1 + 19)
      assert_equal 60, sizes['can0.b']
      # what the devices write to the bus is counted in samples, as before
      assert_equal 12, sizes['a.can_out']
      assert_equal 20, sizes['b.can_out']
    end

    # The demux driver's inputs without needs_reliable_connection.
    PLAIN_INPUTS = GeneratorTestHelper::FILES['models/orogen/demux.orogen'].sub('.needs_reliable_connection', '')

    def test_a_bus_model_that_does_not_override_policies
      files = LAZY_BUS.merge('models/devices/lazy_can.rb' => LAZY_BUS['models/devices/lazy_can.rb']
                                                             .sub('lazy_dispatch: true', 'override_policy: false'),
                             'models/orogen/demux.orogen' => PLAIN_INPUTS)
      plan = generate(lazy_can0, files).plan
      assert_equal({ 'type' => 'data' }, plan.connections_to('can0', 'wa').first.policy)
      @loaded_apps.pop.unload
      plan = generate(on_can0, 'models/orogen/demux.orogen' => PLAIN_INPUTS).plan
      assert_equal({ 'type' => 'buffer', 'size' => 20 }, plan.connections_to('can0', 'wa').first.policy)
    end
  end
end
