# frozen_string_literal: true

require 'syskit/checks/can_timing'

module Syskit
  # `syskit check`: loads everything in an app, generates every profile on
  # every robot configuration, and reports all the problems found, including
  # the ones no generation error shows (overlapping CAN filters, CAN
  # frames that can miss their deadlines).
  class Check
    attr_reader :app, :problems

    def initialize(app)
      @app = app
      @problems = []
    end

    # Problems are kept in the order they are found: loading first, then
    # each profile. A profile whose own files failed to load is not
    # generated: that would only repeat the loading problems.
    def run
      app.load(robots: :all, everything: true)
      @problems.concat(app.problems)
      @problems << opaque_typekits_note unless app.opaque_typekits.empty?
      failed_files = app.errors.filter_map { |p| p.location&.path }.uniq
      app.profiles.values.sort_by(&:name).each { |profile| check_profile(profile, failed_files) }
      @problems = @problems.uniq { |p| [p.class, p.message, p.location.to_a] }
      self
    end

    def errors
      problems.grep_v(Warning)
    end

    def warnings
      problems.grep(Warning)
    end

    private

    def opaque_typekits_note
      names = app.opaque_typekits.keys.sort
      Warning.new("typekits without a description, their types taken as opaque: #{names.join(', ')}",
                  location: app.opaque_typekits.values.first,
                  hint: 'describe one in models/typekits/NAME.rb (struct, enum, opaque) to have its values checked')
    end

    def check_profile(profile, failed_files)
      @problems.concat(Checks::CanFilters.new(profile.robot).warnings)
      @problems.concat(Checks::CanTiming.new(profile).problems)
      return if profile_files(profile).intersect?(failed_files)

      app.robot_configs.each_key { |robot| generate(profile, robot) }
    end

    def profile_files(profile)
      ([profile.declared_at] + profile.robot.devices.map(&:declared_at)).compact.map(&:path).uniq
    end

    def generate(profile, robot)
      Network::Generator.plan_profile(app, profile, robot: robot)
    rescue ErrorList => e
      @problems.concat(e.errors)
    rescue Syskit::Error => e
      @problems << e
    end
  end

  module Checks
    # Devices on one CAN bus whose filters overlap receive each other's
    # frames. Filters are grouped by mask: within a mask, overlapping means
    # equal ids (a hash lookup); across two masks, it means equal ids once
    # both masks are applied, so no pair of filters is ever compared
    # directly.
    class CanFilters
      def initialize(robot)
        @robot = robot
      end

      def warnings
        @robot.devices.grep(Robot::ComBus).flat_map { |bus| bus_warnings(bus) }
      end

      private

      def bus_warnings(bus)
        # Standard and extended filters never match the same frame.
        by_kind = { false => [], true => [] }
        bus.each_attached_device do |dev|
          next unless dev.bus_to_client? && dev.respond_to?(:can_id) && (can_id = dev.can_id)

          filter = CAN::Filter.new(*can_id)
          by_kind[filter.extended?] << [dev, filter]
        end
        pairs = by_kind.each_value.flat_map { |filtered| overlapping_pairs(filtered) }
        pairs.sort_by { |a, b| [a.declared_at.to_a, b.declared_at.to_a] }.map { |a, b| warning(bus, a, b) }
      end

      def overlapping_pairs(filtered)
        by_mask = filtered.group_by { |_, f| f.mask }.to_a
        pairs = []
        by_mask.each_with_index do |(mask, group), i|
          same_mask_pairs(group, pairs)
          by_mask.drop(i + 1).each { |other_mask, other| pairs.concat(cross_pairs(group, other, mask & other_mask)) }
        end
        pairs
      end

      # Same mask: ids lie within the mask, so only equal ids overlap. Most
      # ids are unique: a list is made only for an id seen twice.
      def same_mask_pairs(group, pairs)
        first = {}
        more = {}
        group.each do |dev, filter|
          if (seen = first[filter.id])
            (more[filter.id] ||= [seen]) << dev
          else
            first[filter.id] = dev
          end
        end
        more.each_value { |same| same.combination(2) { |a, b| pairs << [a, b] } }
      end

      # Pairs across two masks: equal ids once both masks are applied.
      def cross_pairs(left, right, common)
        index = left.group_by { |_, f| f.id & common }
        right.flat_map do |dev, filter|
          (index[filter.id & common] || []).map { |other, _| [other, dev] }
        end
      end

      def warning(bus, first, second)
        Warning.new(
          "#{first} (#{CAN::Filter.new(*first.can_id)}) and #{second} (#{CAN::Filter.new(*second.can_id)}) " \
          "on #{bus} have overlapping filters: both receive some of the same frames " \
          "(#{first} is declared at #{first.declared_at})",
          location: second.declared_at,
          hint: 'narrow one of the masks so that no frame id passes both filters'
        )
      end
    end
  end
end
