# frozen_string_literal: true

require 'syskit/can'
require 'syskit/bus/frame'
require 'syskit/bus/errors'

module Syskit
  module Bus
    # Which devices of a bus receive a frame, from the devices' CAN filters.
    #
    # A device receives a frame when it reads from the bus (bus_to_client)
    # and (frame_id & mask) == id for its can_id filter. Standard (11-bit)
    # and extended (29-bit) frames are kept apart: a filter whose id or mask
    # exceeds 0x7FF is an extended filter and matches extended frames only;
    # every other filter matches standard frames only (see CAN::Filter).
    #
    # Filters are grouped by mask: one hash per distinct mask, keyed by
    # id & mask, so a frame costs one lookup per distinct mask, whatever the
    # number of devices. The answer for a frame key is then remembered, since
    # a bus carries few distinct ids.
    class Dispatcher
      NONE = [].freeze
      # Beyond this many distinct keys, answers are computed, not remembered,
      # so that a log of random ids cannot grow the cache without bound.
      CACHE_LIMIT = 1 << 16

      # A device as the dispatcher sees it. +status+ is :filtered (receives
      # by its filter), :no_filter (reads the bus but declares no can_id, so
      # receives nothing by filter) or :write_only (bus_to_client: false).
      Device = Struct.new(:name, :can_filter, :status)

      attr_reader :bus, :devices

      # The dispatcher of bus +bus+ in +plan+ (a Network::Plan).
      def self.from_plan(plan, bus)
        devices = plan.devices_on(bus)
        return new(bus, devices) if devices.any?

        buses = plan.devices.filter_map(&:bus).uniq.sort
        known = plan.find_device(bus) ? "#{bus} has no device attached" : "the plan has no bus named '#{bus}'"
        hint = buses.empty? ? 'this profile has no device attached to a bus' : "buses with devices: #{buses.join(', ')}"
        raise UnknownName.new("#{known}#{Naming.did_you_mean(bus, buses)}", hint: hint)
      end

      # +plan_devices+ are Network::Plan::Device entries (name, bus_to_client,
      # attributes['can_id'] = [id, mask]).
      def initialize(bus, plan_devices)
        @bus = bus
        @devices = plan_devices.map { |d| device_entry(d) }.sort_by(&:name).freeze
        receiving = @devices.select { |d| d.status == :filtered }
        @standard, @extended = groups_by_kind(receiving)
        # Write-only devices may declare the ids they send: reports use them
        # to explain frames that nobody receives.
        @writers = groups_by_kind(@devices.select { |d| d.status == :write_only && d.can_filter })
        @cache = {}
      end

      # The names of the devices that receive frames with +key+ (Frame.key:
      # the id, with Frame::EFF_FLAG for an extended frame), sorted; a frozen
      # array, shared between calls.
      def receivers(key)
        @cache[key] || remember(key, lookup(key))
      end

      # Same as #receivers, without the cache: one hash lookup per distinct
      # mask of the frame's kind.
      def lookup(key)
        (key & Frame::EFF_FLAG).zero? ? match(@standard, key) : match(@extended, key & Frame::EFF_MASK)
      end

      # The names of the write-only devices whose can_id filter matches
      # +key+: the frames they send, when they declare them.
      def writers(key)
        extended = key & Frame::EFF_FLAG != 0
        match(@writers[extended ? 1 : 0], key & Frame::EFF_MASK)
      end

      # Number of distinct masks, standard and extended.
      def mask_count
        @standard.size + @extended.size
      end

      private

      def match(groups, id)
        found = nil
        groups.each do |mask, by_id|
          names = by_id[id & mask]
          found = found ? found + names : names if names
        end
        found ? found.sort.freeze : NONE
      end

      def remember(key, names)
        @cache[key] = names if @cache.size < CACHE_LIMIT
        names
      end

      def device_entry(device)
        can_id = device.attributes && device.attributes['can_id']
        filter = can_id && CAN::Filter.new(*can_id)
        status = if !device.bus_to_client then :write_only
                 elsif filter then :filtered
                 else :no_filter
                 end
        Device.new(device.name, filter, status).freeze
      end

      # [standard groups, extended groups] of +devices+ (see #mask_groups).
      def groups_by_kind(devices)
        extended, standard = devices.partition { |d| d.can_filter.extended? }
        [mask_groups(standard), mask_groups(extended)]
      end

      # [[mask, { id => [names] }], ...]: an array, since it is iterated for
      # every frame and has few entries.
      def mask_groups(devices)
        devices.group_by { |d| d.can_filter.mask }.sort.map do |mask, group|
          by_id = group.group_by { |d| d.can_filter.id }.transform_values { |same| same.map(&:name).freeze }
          [mask, by_id.freeze].freeze
        end.freeze
      end
    end
  end
end
