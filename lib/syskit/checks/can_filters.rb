# frozen_string_literal: true

module Syskit
  module Checks
    # Devices on one CAN bus whose filters overlap receive each other's
    # frames. Filters are grouped by mask: within a mask, overlapping means
    # equal ids (a hash lookup); across two masks, it means equal ids once
    # both masks are applied, so no pair of filters is ever compared
    # directly.
    #
    # Overlaps are reported by group, not by pair, so that the output grows
    # with the devices: one warning for the devices sharing one filter, and
    # one per pair of masks and masked id for the devices of either mask
    # whose ids agree there (each of one side overlaps each of the other).
    class CanFilters
      # Devices whose filters overlap: +same+ when they all have one filter
      # (+other+ empty), or every device of +same+ overlapping every device
      # of +other+ (two masks). Devices are in declaration order; +culprit+
      # is the first one that overlaps a device declared before it.
      Overlap = Struct.new(:bus, :same, :other, :culprit) do
        # Every pair of overlapping devices (for tests: quadratic).
        def pairs
          other.empty? ? same.combination(2).to_a : same.product(other)
        end

        def devices
          same + other
        end
      end

      def initialize(robot)
        @robot = robot
      end

      def warnings
        unmatchable.map { |dev, filter| unmatchable_warning(dev, filter) } +
          overlaps.map { |overlap| warning(overlap) }
      end

      # The devices, and their filters, that no frame can reach: the id has
      # bits outside the mask. can_id stores such a filter as given (the
      # seed's own test sets one), so this check is where a user hears of it.
      def unmatchable
        @robot.each_master_device.grep(Robot::ComBus).flat_map do |bus|
          bus.each_attached_device.filter_map do |dev|
            filter = filter_of_reader(dev)
            [dev, filter] if filter && !filter.matchable?
          end
        end
      end

      # The overlapping groups of every bus, in the order of the devices
      # their warnings point at.
      def overlaps
        @robot.each_master_device.grep(Robot::ComBus).flat_map { |bus| bus_overlaps(bus) }
      end

      private

      def bus_overlaps(bus)
        # Standard and extended filters never match the same frame.
        by_kind = { false => [], true => [] }
        order = {}.compare_by_identity
        bus.each_attached_device do |dev|
          order[dev] = order.size
          # A filter no frame passes overlaps nothing.
          next unless (filter = filter_of_reader(dev)) && filter.matchable?

          by_kind[filter.extended?] << [dev, filter]
        end
        groups = by_kind.each_value.flat_map { |filtered| overlapping_groups(filtered) }
        # By culprit, then as found (sort_by alone is not stable).
        groups.each_with_index
              .map { |(same, other), i| [overlap(bus, same.sort_by(&order), other.sort_by(&order), order), i] }
              .sort_by { |overlap, i| [order[overlap.culprit], i] }.map(&:first)
      end

      # The culprit of two sides is the first device of the side whose first
      # device comes second.
      def overlap(bus, same, other, order)
        culprit = if other.empty? then same[1]
                  elsif order[same.first] < order[other.first] then other.first
                  else same.first
                  end
        Overlap.new(bus, same, other, culprit)
      end

      # [same, other] device lists: see Overlap.
      def overlapping_groups(filtered)
        by_mask = filtered.group_by { |_, f| f.mask }.to_a
        groups = []
        by_mask.each_with_index do |(mask, group), i|
          same_filter_groups(group, groups)
          by_mask.drop(i + 1).each { |other_mask, other| cross_groups(group, other, mask & other_mask, groups) }
        end
        groups
      end

      # Same mask: ids lie within the mask, so only equal ids overlap. Most
      # ids are unique: a list is made only for an id seen twice.
      def same_filter_groups(group, groups)
        first = {}
        more = {}
        group.each do |dev, filter|
          if (seen = first[filter.id])
            (more[filter.id] ||= [seen]) << dev
          else
            first[filter.id] = dev
          end
        end
        more.each_value { |same| groups << [same, []] }
      end

      # Across two masks: the devices of either side whose ids are equal
      # once both masks are applied.
      def cross_groups(left, right, common, groups)
        index = left.group_by { |_, f| f.id & common }
        right.group_by { |_, f| f.id & common }.each do |key, devices|
          matches = index[key]
          groups << [matches.map(&:first), devices.map(&:first)] if matches
        end
      end

      # The filter of a device that reads the bus (write-only devices
      # receive nothing), when it has one: an id and a mask. What a bus
      # model's own can_id stores may be anything else (its filter block
      # decides): that is not a CAN filter these checks can judge.
      def filter_of_reader(dev)
        return unless dev.bus_to_client? && dev.respond_to?(:can_id) && (can_id = dev.can_id)
        return unless can_id.is_a?(Array) && can_id.size == 2 && can_id.all?(Integer)

        CAN::Filter.new(*can_id)
      end

      def unmatchable_warning(dev, filter)
        Warning.new(
          format('%<dev>s on %<bus>s has a filter that can never match (%<filter>s): the id has bits outside ' \
                 'the mask (id & mask = 0x%<both>X), so no frame reaches it',
                 dev: dev, bus: dev.bus, filter: filter, both: filter.id & filter.mask),
          location: dev.dsl_attribute_location(:can_id),
          hint: format('a frame reaches the device when frame_id & mask == id: set every bit of the id in the ' \
                       'mask, e.g. can_id(0x%<id>X, 0x%<mask>X)', id: filter.id, mask: filter.id | filter.mask)
        )
      end

      def warning(overlap)
        devices = overlap.devices
        return pair_warning(overlap.bus, *devices) if devices.size == 2

        Warning.new(overlap.other.empty? ? same_filter_message(overlap) : groups_message(overlap),
                    location: overlap.culprit.declared_at,
                    hint: 'narrow the masks, or give the devices other ids, so that no frame id passes two filters')
      end

      def pair_warning(bus, first, second)
        Warning.new(
          "#{first} (#{filter_of(first)}) and #{second} (#{filter_of(second)}) " \
          "on #{bus} have overlapping filters: both receive some of the same frames " \
          "(#{first} is declared at #{first.declared_at})",
          location: second.declared_at,
          hint: 'narrow one of the masks so that no frame id passes both filters'
        )
      end

      def same_filter_message(overlap)
        devices = overlap.same
        "#{devices.size} devices on #{overlap.bus} have overlapping filters: they all have the filter " \
          "#{filter_of(devices.first)} and receive the same frames (#{names(devices)}; " \
          "#{devices.first} is declared at #{devices.first.declared_at})"
      end

      def groups_message(overlap)
        first = overlap.same.first.equal?(overlap.culprit) ? overlap.other.first : overlap.same.first
        "#{side(overlap.same)} and #{side(overlap.other)} on #{overlap.bus} have overlapping filters: each " \
          'device of one side receives some of the frames of each device of the other ' \
          "(#{first} is declared at #{first.declared_at})"
      end

      # Devices of one mask: their names and ids, then the mask.
      def side(devices)
        return "#{devices.first} (#{filter_of(devices.first)})" if devices.size == 1

        ids = devices.map { |dev| format("'%<name>s' (id 0x%<id>X)", name: dev.name, id: dev.can_id.first) }
        "devices #{ids.join(', ')} (mask 0x#{format('%X', CAN::Filter.new(*devices.first.can_id).mask)})"
      end

      def names(devices)
        devices.map { |dev| "'#{dev.name}'" }.join(', ')
      end

      def filter_of(device)
        CAN::Filter.new(*device.can_id)
      end
    end
  end
end
