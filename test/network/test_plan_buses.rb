# frozen_string_literal: true

require 'helper'
require 'json'

module Syskit
  module Network
    # The plan lists each CAN bus with its bitrate, utilisation and the
    # frames declared on its wire.
    class TestPlanBuses < Minitest::Test
      EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')

      def plan(actions: [])
        app = load_app(EXAMPLE)
        Generator.plan_profile(app, AwesomeRobot::Profiles::Live::Base.syskit_profile, actions: actions).plan
      end

      def test_each_bus_with_a_wire_of_its_own
        buses = plan.buses
        # n2k is attached to can0: its frames are on can0's wire.
        assert_equal %w[can0 can1], buses.map(&:name)
        can0 = buses.first
        assert_equal [250_000, Rational(3114, 100_000)], [can0.bitrate, can0.utilization]
        assert_equal [0x1234, 0x80, 0x301, 0x302, 0x303, 0x19F21123], can0.frames.map(&:id)
        assert_equal 'fuel_level', can0.frames.last.device
      end

      def test_frame_entries
        sync = plan.buses.first.frames[1]
        assert_equal [0, Rational(1, 100), Rational(1, 500), Rational(1, 10_000), 'sync'],
                     [sync.bytes, sync.period, sync.deadline, sync.jitter, sync.device]
        assert_match %r{\Amodels/profiles/live/base.rb:\d+\z}, sync.declared_at
      end

      def test_json_and_text
        plan = self.plan
        json = JSON.parse(Render::JSON.render(plan))['buses']
        assert_equal({ 'id' => 0x80, 'extended' => false, 'bytes' => 0, 'device' => 'sync', 'period' => 0.01,
                       'deadline' => 0.002, 'jitter' => 0.0001 },
                     json.first['frames'][1].except('declared_at'))
        assert_equal [0.03114, 250_000], json.first.values_at('utilization', 'bitrate')
        text = Render::Text.render(plan)[/^Buses.*/m]
        assert_includes text, "  can0  CommonModels::Devices::Bus::CAN, driven by can0 (canbus::Task)\n    " \
                              "250 kbit/s, utilisation 3.1 %\n"
        assert_match(/^    frames\n      00001234  temperature_sensor  2 bytes, period 100/, text)
        assert_match(/^      080       sync                0 bytes, period 10 ms, deadline 2 ms, jitter 0.1 ms$/, text)
        assert_includes text, "  can1  CommonModels::Devices::Bus::CAN, driven by can1 (simple_can::Task)\n    " \
                              "1 Mbit/s, utilisation 54.1 %\n"
        # Each bus's devices, a bus through a bus followed by its own, with their filters in hex.
        n2k = '      n2k  +AwesomeRobot::Devices::N2k::Bus  +id 0x1F21100 mask 0x3FFFF00\n'
        fuel_level = '        fuel_level  +AwesomeRobot::Devices::N2k::FluidLevel\n'
        assert_match(Regexp.new("^    devices\n#{n2k}#{fuel_level}      sync  "), text)
      end

      def test_a_plan_without_can_bus_lists_none
        only_gps = plan(actions: ['gps_dev'])
        assert_empty only_gps.buses
        refute_match(/^Buses/, Render::Text.render(only_gps))
        assert_equal [], JSON.parse(Render::JSON.render(only_gps))['buses']
      end
    end
  end
end
