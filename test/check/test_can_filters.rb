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
        readers = robot.each_master_device.select { |d| d.attached? && d.bus_to_client? }
        readers.combination(2).select do |a, b|
          first = CAN::Filter.new(*a.can_id)
          second = CAN::Filter.new(*b.can_id)
          a.bus.equal?(b.bus) && first.extended? == second.extended? && first.overlap?(second)
        end
      end

      def named_pairs(pairs)
        pairs.map { |pair| pair.map(&:name).sort }.sort
      end

      # Groups stand for pairs: each pair of overlapping devices is in
      # exactly one group, and a group holds no pair that does not overlap.
      def test_finds_the_pairs_that_comparing_every_pair_finds
        robot = load_app(my_app(random_robot(Random.new(20_261_123), 4, 60))).profiles.values.first.robot
        check = CanFilters.new(robot)
        found = named_pairs(check.overlaps.flat_map(&:pairs))
        expected = named_pairs(every_overlapping_pair(robot))
        assert_operator expected.size, :>, 20
        assert_equal expected, found
        assert_equal found.uniq, found
        assert_equal check.overlaps.size, check.warnings.size
        assert_operator check.warnings.size, :<, found.size
      end

      def robot_of(robot_block)
        load_app(my_app(robot_block)).profiles.values.first.robot
      end

      def bus_of(lines)
        "com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\nthrough 'can0' do\n#{lines.join("\n")}\nend\n"
      end

      # 2n devices sharing one id, on two masks: one warning per group, and
      # the output grows with the devices, not with their n^2 pairs.
      def test_overlaps_are_reported_by_group_with_output_linear_in_the_devices
        sizes = [100, 200].map do |n|
          lines = Array.new(n) { |i| "device(Devices::TemperatureSensor, as: 'a#{i}').can_id(0x120, 0x7ff)" } +
                  Array.new(n) { |i| "device(Devices::TemperatureSensor, as: 'b#{i}').can_id(0x100, 0x700)" }
          warnings = CanFilters.new(robot_of(bus_of(lines))).warnings
          Syskit.app.unload
          assert_groups(warnings, n)
          warnings.sum { |w| w.message.size }
        end
        assert_in_delta 2.0, sizes[1].fdiv(sizes[0]), 0.2
      end

      # a* share a filter, b* share a filter, and each a overlaps each b.
      def assert_groups(warnings, count)
        assert_equal 3, warnings.size
        assert_match(/\A#{count} devices on bus 'can0' have overlapping filters: they all have the filter id 0x120/,
                     warnings[0].message)
        assert_match(/\Adevices 'a0' \(id 0x120\), 'a1' \(id 0x120\).* \(mask 0x7FF\) and devices 'b0'/,
                     warnings[1].message)
        assert_equal(['models/profiles/base.rb', 12], warnings[0].location.to_a.then { |p, l| [p[/models.*/], l] })
      end

      # A bus model of the app's own may store anything in can_id (its
      # filter block decides): the checks judge only an id and a mask.
      def test_a_can_id_that_is_not_an_id_and_a_mask_is_left_alone
        bus = <<~RUBY
          module MyApp
            module Devices
              com_bus_type 'Loose', message_type: '/canbus/Message' do
                extend_attached_device_configuration do
                  dsl_attribute(:can_id) { |*args| args }
                end
              end
            end
          end
        RUBY
        # No driver drives this bus: what the check reads is the robot.
        app = load_app(my_app(<<~ROBOT, 'models/devices/loose.rb' => bus), problems: true)
          com_bus Devices::Loose, as: 'bus0'
          through 'bus0' do
            device(Devices::TemperatureSensor, as: 'a').can_id(0x10, 1e400)
            device(Devices::TemperatureSensor, as: 'b').can_id(0x10, 0x7ff, 3)
            device(Devices::TemperatureSensor, as: 'c').can_id(0x1, 0xf)
            device(Devices::TemperatureSensor, as: 'd').can_id(0x1, 0xf)
          end
        ROBOT
        warnings = CanFilters.new(app.profiles.values.first.robot).warnings
        assert_equal 1, warnings.size
        assert_match(/device 'c' .* and device 'd' .* have overlapping filters/, warnings.first.message)
      end

      def test_a_device_overlapping_devices_of_another_mask_is_one_warning
        robot = robot_of(bus_of(["device(Devices::TemperatureSensor, as: 'a').can_id(0x120, 0x7f0)",
                                 "device(Devices::TemperatureSensor, as: 'b').can_id(0x100, 0x700)",
                                 "device(Devices::TemperatureSensor, as: 'c').can_id(0x12f, 0x7ff)",
                                 "device(Devices::TemperatureSensor, as: 'd').can_id(0x140, 0x7f0)"]))
        warnings = CanFilters.new(robot).warnings.map { |w| [w.location.lineno, w.message] }.sort
        # a and d (mask 0x7F0) each overlap b (0x700): one group, at b's line
        assert_equal [[12, "devices 'a' (id 0x120), 'd' (id 0x140) (mask 0x7F0) and device 'b' (id 0x100 mask 0x700) " \
                           "on bus 'can0' have overlapping filters: each device of one side receives some of the " \
                           "frames of each device of the other (device 'a' is declared at models/profiles/base.rb:11)"],
                      [13, "device 'a' (id 0x120 mask 0x7F0) and device 'c' (id 0x12F mask 0x7FF) on bus 'can0' " \
                           'have overlapping filters: both receive some of the same frames ' \
                           "(device 'a' is declared at models/profiles/base.rb:11)"],
                      [13, "device 'b' (id 0x100 mask 0x700) and device 'c' (id 0x12F mask 0x7FF) on bus 'can0' " \
                           'have overlapping filters: both receive some of the same frames ' \
                           "(device 'b' is declared at models/profiles/base.rb:12)"]], warnings
      end
    end
  end
end
