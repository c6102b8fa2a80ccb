# frozen_string_literal: true

require 'helper'
require 'syskit/bus/dispatcher'

module Syskit
  module Bus
    # Which devices receive a frame.
    class TestDispatcher < Minitest::Test
      def dev(name, can_id = nil, bus_to_client: true)
        Network::Plan::Device.with(name: name, bus: 'can0', bus_to_client: bus_to_client, client_to_bus: true,
                                   attributes: can_id ? { 'can_id' => can_id } : {})
      end

      def std(id)
        Frame.key(id, false)
      end

      def ext(id)
        Frame.key(id, true)
      end

      def test_a_filter_is_extended_when_its_id_or_mask_exceeds_11_bits
        refute CAN::Filter.new(0x300, 0x7F0).extended?
        refute CAN::Filter.new(0x7FF, 0x7FF).extended?
        assert CAN::Filter.new(0x120, 0x1FFFFFFF).extended?
        assert CAN::Filter.new(0x800, 0x800).extended?
        assert CAN::Filter.new(0, 0x800).extended?
      end

      def test_standard_filters_match_standard_frames_only
        d = Dispatcher.new('can0', [dev('a', [0x300, 0x7F0])])
        assert_equal ['a'], d.receivers(std(0x305))
        assert_equal [], d.receivers(ext(0x305))
        assert_equal [], d.receivers(std(0x405))
      end

      def test_extended_filters_match_extended_frames_only
        d = Dispatcher.new('can0', [dev('a', [0x120, 0x1FFFFFFF]), dev('b', [0x18FEF100, 0x1FFFFF00])])
        assert_equal ['a'], d.receivers(ext(0x120))
        assert_equal [], d.receivers(std(0x120))
        assert_equal ['b'], d.receivers(ext(0x18FEF1AB))
        assert_equal [], d.receivers(ext(0x18FEF2AB))
      end

      def test_every_matching_device_is_returned_sorted
        d = Dispatcher.new('can0', [dev('z', [0x120, 0x7F0]), dev('a', [0x100, 0x700]), dev('m', [0x125, 0x7FF]),
                                    dev('b', [0x125, 0x7FF])])
        assert_equal %w[a b m z], d.receivers(std(0x125))
        assert_equal %w[a z], d.receivers(std(0x12F))
        assert_same d.receivers(std(0x125)), d.receivers(std(0x125))
      end

      def test_devices_that_cannot_receive
        d = Dispatcher.new('can0', [dev('w', [0x80, 0x7FF], bus_to_client: false), dev('n'), dev('a', [0x80, 0x7FF])])
        statuses = d.devices.to_h { |x| [x.name, x.status] }
        assert_equal({ 'a' => :filtered, 'n' => :no_filter, 'w' => :write_only }, statuses)
        assert_equal ['a'], d.receivers(std(0x80))
      end

      def test_write_only_devices_are_named_as_the_likely_senders_of_their_ids
        d = Dispatcher.new('can0', [dev('sync', [0x80, 0x7FF], bus_to_client: false), dev('a', [0x300, 0x7F0]),
                                    dev('w', nil, bus_to_client: false)])
        assert_equal [], d.receivers(std(0x80))
        assert_equal ['sync'], d.writers(std(0x80))
        assert_equal [], d.writers(ext(0x80))
        assert_equal [], d.writers(std(0x305))
      end

      def test_one_hash_per_distinct_mask
        devices = Array.new(20) { |i| dev("d#{i}", [0x100 + (i * 0x10), 0x7F0]) } +
                  Array.new(5) { |i| dev("e#{i}", [0x1000 + i, 0x1FFFFFFF]) }
        assert_equal 2, Dispatcher.new('can0', devices).mask_count
      end

      # The grouped lookup answers what testing every filter would.
      def test_agrees_with_testing_every_filter
        random = Random.new(1)
        devices = random_devices(random)
        d = Dispatcher.new('can0', devices)
        filters = d.devices.map { |x| [x.name, x.can_filter] }
        2000.times do
          id, extended = random_id(random, devices)
          next if !extended && id > 0x7FF

          expected = filters.select { |_, f| f.extended? == extended && f.match?(id) }.map(&:first).sort
          assert_equal expected, d.receivers(Frame.key(id, extended)), format('%<id>X', id: id)
        end
      end

      # 40 devices whose filters have six different masks, of both kinds.
      def random_devices(random)
        Array.new(40) do |i|
          mask = [0x7FF, 0x7F0, 0x700, 0x1FFFFFFF, 0x3FFFF00, 0x1FFFF000][random.rand(6)]
          dev("d#{i}", [random.rand(0x2000_0000) & mask, mask])
        end
      end

      # An id and whether it is extended; half of them near a device's id,
      # so that filters match often enough to test something.
      def random_id(random, devices)
        extended = random.rand(2).zero?
        id = extended ? random.rand(0x2000_0000) : random.rand(0x800)
        id = devices[random.rand(40)].attributes['can_id'][0] | (id & 0xF) if random.rand(2).zero?
        [id, extended]
      end

      def test_from_plan_reads_the_devices_of_the_bus
        plan = Network::Plan.new(profile: 'P', robot: 'default', connections: [], order: [], tasks: [],
                                 devices: [dev('a', [0x300, 0x7F0]), dev('can0').tap { |d| d.bus = nil }])
        assert_equal ['a'], Dispatcher.from_plan(plan, 'can0').devices.map(&:name)
        assert_syskit_error(/the plan has no bus named 'can1'/, hint: /buses with devices: can0/) do
          Dispatcher.from_plan(plan, 'can1')
        end
        assert_syskit_error(/a has no device attached/, hint: /buses with devices: can0/) do
          Dispatcher.from_plan(plan, 'a')
        end
      end
    end
  end
end
