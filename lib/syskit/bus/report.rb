# frozen_string_literal: true

require 'syskit/bus/frame'

module Syskit
  module Bus
    # What the devices of a bus received, from the Traffic seen on it: per
    # device counts, the ids nobody receives and the ids several devices
    # receive. A value: renderers (ReportText, #to_h for JSON) only read it.
    class Report
      # One device of the bus. +status+: see Dispatcher::Device.
      DeviceRow = Struct.new(:name, :status, :filter, :frames, :keys, :first, :last, keyword_init: true) do
        # Mean reception rate in frames/s: intervals between the first and
        # last frame, over the time between them (nil under two frames).
        def rate
          Report.rate(frames, first, last)
        end
      end
      # One frame key (id + extended flag), the devices receiving it and,
      # for ids nobody receives, the write-only devices whose can_id matches
      # (most likely their senders).
      IdRow = Struct.new(:key, :frames, :first, :last, :devices, :writers, keyword_init: true)

      attr_reader :bus, :traffic, :devices, :unclaimed, :overlaps, :source

      # Frames per second between +first+ and +last+, in microseconds (see
      # DeviceRow#rate).
      def self.rate(frames, first, last)
        return unless frames > 1 && first && last && last > first

        (frames - 1) * 1e6 / (last - first)
      end

      # Microseconds to seconds, for people and JSON.
      def self.seconds(microseconds)
        microseconds && (microseconds / 1e6)
      end

      # +source+: where the traffic comes from, shown as is ('log',
      # 'interface', 'profile', 'robot', 'malformed'...).
      def initialize(dispatcher, traffic, source: {})
        @bus = dispatcher.bus
        @traffic = traffic
        @source = source
        build(dispatcher)
      end

      # Seconds between the first and the last frame.
      def duration
        Report.seconds(traffic.last_time - traffic.first_time) if traffic.first_time
      end

      # The report as plain data, for --format json.
      def to_h
        {
          'bus' => bus, 'source' => source,
          'frames' => { 'total' => traffic.frames, 'standard' => traffic.standard, 'extended' => traffic.extended,
                        'fd' => traffic.fd, 'rtr' => traffic.rtr, 'error' => traffic.errors },
          'first_time' => Report.seconds(traffic.first_time), 'last_time' => Report.seconds(traffic.last_time),
          'duration' => duration,
          'devices' => devices.map { |d| device_hash(d) },
          'unclaimed' => unclaimed.map { |r| unclaimed_hash(r) },
          'overlaps' => overlaps.map { |r| id_hash(r).merge('devices' => r.devices) }
        }
      end

      private

      def build(dispatcher)
        rows = dispatcher.devices.to_h do |d|
          [d.name, DeviceRow.new(name: d.name, status: d.status, filter: d.filter, frames: 0, keys: [])]
        end
        @unclaimed = []
        @overlaps = []
        traffic.ids.keys.sort.each do |key|
          stats = traffic.ids[key]
          names = dispatcher.receivers(key)
          names.each { |name| add(rows.fetch(name), key, stats) }
          @unclaimed << id_row(key, stats, writers: dispatcher.writers(key)) if names.empty?
          @overlaps << id_row(key, stats, names) if names.size > 1
        end
        @devices = rows.values
      end

      def add(row, key, stats)
        row.frames += stats.count
        row.keys << key
        row.first = stats.first if stats.first && (row.first.nil? || stats.first < row.first)
        row.last = stats.last if stats.last && (row.last.nil? || stats.last > row.last)
      end

      def id_row(key, stats, names = [], writers: [])
        IdRow.new(key: key, frames: stats.count, first: stats.first, last: stats.last, devices: names, writers: writers)
      end

      def id_hash(row)
        { 'id' => row.key & Frame::EFF_MASK, 'hex' => Frame.key_to_s(row.key),
          'extended' => row.key & Frame::EFF_FLAG != 0, 'frames' => row.frames }
      end

      def unclaimed_hash(row)
        id_hash(row).merge('first_time' => Report.seconds(row.first), 'last_time' => Report.seconds(row.last),
                           'write_only_matches' => row.writers)
      end

      def device_hash(row)
        filter = row.filter && { 'id' => row.filter.id, 'mask' => row.filter.mask, 'extended' => row.filter.extended? }
        {
          'name' => row.name, 'status' => row.status.to_s, 'filter' => filter, 'frames' => row.frames,
          'distinct_ids' => row.keys.size, 'ids' => row.keys.map { |k| Frame.key_to_s(k) },
          'first_time' => Report.seconds(row.first), 'last_time' => Report.seconds(row.last), 'rate' => row.rate&.round(3)
        }
      end
    end
  end
end
