# frozen_string_literal: true

require 'helper'
require 'syskit/check'

module Syskit
  module Checks
    # The filter-overlap check finds exactly the pairs that comparing every
    # filter with every other would find.
    class TestCanFilters < Minitest::Test
      # Few masks and ids, so that equal ids, shared masks, standard and
      # extended filters and write-only devices all occur.
      MASKS = [0x7FF, 0x7F0, 0x700, 0x1FFFFFFF, 0x1FFFFF00].freeze

      # +buses+ CAN buses of +count+ devices each.
      def random_robot(random, buses, count)
        Array.new(buses) do |b|
          lines = Array.new(count) do |i|
            mask = MASKS.sample(random: random)
            id = random.rand(0x2000) & mask
            write_only = random.rand(8).zero? ? ', bus_to_client: false' : ''
            "  device(Devices::TemperatureSensor, as: 'd#{b}_#{i}'#{write_only})" \
              ".can_id(0x#{id.to_s(16)}, 0x#{mask.to_s(16)})"
          end
          "com_bus CommonModels::Devices::Bus::CAN, as: 'can#{b}'\nthrough 'can#{b}' do\n#{lines.join("\n")}\nend\n"
        end.join
      end

      # Every pair of devices on one bus whose filters overlap, found the slow way.
      def every_overlapping_pair(robot)
        readers = robot.devices.select { |d| d.attached? && d.bus_to_client? }
        readers.combination(2).select do |a, b|
          first = CAN::Filter.new(*a.can_id)
          second = CAN::Filter.new(*b.can_id)
          a.bus.equal?(b.bus) && first.extended? == second.extended? && first.overlap?(second)
        end
      end

      def named_pairs(pairs)
        pairs.map { |pair| pair.map(&:name).sort }.sort
      end

      def test_finds_the_pairs_that_comparing_every_pair_finds
        robot = load_app(my_app(random_robot(Random.new(20_261_123), 4, 60))).profiles.values.first.robot
        warnings = CanFilters.new(robot).warnings
        found = warnings.map { |w| w.message.scan(/device '(\w+)'/).first(2).flatten.sort }.sort
        expected = named_pairs(every_overlapping_pair(robot))
        assert_operator expected.size, :>, 20
        assert_equal expected, found
      end
    end
  end
end
