# frozen_string_literal: true

require 'syskit/bus/frame'
require 'syskit/bus/declared_traffic'

module Syskit
  module Bus
    # What the devices of a bus received, from the Traffic seen on it: per
    # device counts, the ids nobody receives and the ids several devices
    # receive. A value: renderers (ReportText, #to_h for JSON) only read it.
    class Report
      # One device of the bus. +status+: see Dispatcher::Device; +rate+: see
      # Report.rate.
      DeviceRow = Struct.new(:name, :status, :can_filter, :frames, :keys, :first_time, :last_time, :rate,
                             keyword_init: true)
      # One frame key (id + extended flag), the devices receiving it and,
      # for ids nobody receives, the write-only devices whose can_id matches
      # (most likely their senders) and the devices that declare the frame
      # (.frame): one no can_id receives is one the host sends them, a
      # command to the device.
      IdRow = Struct.new(:key, :frames, :first_time, :last_time, :devices, :writers, :declared_by,
                         keyword_init: true)

      attr_reader :bus, :traffic, :devices, :unclaimed, :overlaps, :source, :declared

      # The mean rate of a device, in frames/s: its frames over the time the
      # log (or the monitoring) spans, from its first frame to its last, in
      # microseconds. Over the whole span rather than the device's own, so
      # that a device receiving several periodic ids gets the sum of their
      # rates; nil when the span is empty.
      def self.rate(frames, span)
        frames.to_f * 1e6 / span if span&.positive?
      end

      # Microseconds to seconds, for people and JSON.
      def self.seconds(microseconds)
        microseconds && (microseconds / 1e6)
      end

      # +source+: where the traffic comes from, shown as is ('log',
      # 'interface', 'profile', 'robot', 'malformed'...). +declared_bus+:
      # the plan's entry of the bus (Network::Plan::Bus), whose declared
      # frames the traffic is compared with (see DeclaredTraffic).
      def initialize(dispatcher, traffic, source: {}, declared_bus: nil)
        @bus = dispatcher.bus
        @traffic = traffic
        @source = source
        @declared = DeclaredTraffic.new(declared_bus, traffic) if declared_bus
        @declarers = declarers(declared_bus)
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
          'frames' => frames_hash,
          'first_time' => Report.seconds(traffic.first_time), 'last_time' => Report.seconds(traffic.last_time),
          'duration' => duration,
          'devices' => devices.map { |d| device_hash(d) },
          'unclaimed' => unclaimed.map { |r| unclaimed_hash(r) },
          'overlaps' => overlaps.map { |r| id_hash(r).merge('devices' => r.devices) },
          'declared' => declared&.to_h
        }
      end

      private

      def build(dispatcher)
        rows = device_rows(dispatcher)
        @unclaimed = []
        @overlaps = []
        traffic.ids.keys.sort.each do |key|
          stats = traffic.ids[key]
          names = dispatcher.receivers(key)
          names.each { |name| add(rows.fetch(name), key, stats) }
          @unclaimed << id_row(key, stats, writers: dispatcher.writers(key)) if names.empty?
          @overlaps << id_row(key, stats, names) if names.size > 1
        end
        @devices = with_rates(rows.values)
      end

      # Empty rows by device name, filled by #add.
      def device_rows(dispatcher)
        dispatcher.devices.to_h do |d|
          [d.name, DeviceRow.new(name: d.name, status: d.status, can_filter: d.can_filter, frames: 0, keys: [])]
        end
      end

      # Write-only devices receive nothing: they get no rate.
      def with_rates(rows)
        span = traffic.last_time - traffic.first_time if traffic.first_time
        rows.each { |row| row.rate = Report.rate(row.frames, span) unless row.status == :write_only }
      end

      def add(row, key, stats)
        row.frames += stats.frames
        row.keys << key
        first = stats.first_time
        last = stats.last_time
        row.first_time = first if first && (row.first_time.nil? || first < row.first_time)
        row.last_time = last if last && (row.last_time.nil? || last > row.last_time)
      end

      def id_row(key, stats, names = [], writers: [])
        IdRow.new(key: key, frames: stats.frames, first_time: stats.first_time, last_time: stats.last_time,
                  devices: names, writers: writers, declared_by: @declarers.fetch(key, []))
      end

      # Frame key => the devices declaring that frame on the bus.
      def declarers(bus)
        return {} unless bus

        bus.frames.group_by { |f| Frame.key(f.id, f.extended) }.transform_values { |fs| fs.map(&:device).uniq }
      end

      def frames_hash
        { 'total' => traffic.frames, 'standard' => traffic.standard, 'extended' => traffic.extended,
          'fd' => traffic.fd, 'rtr' => traffic.rtr, 'error' => traffic.errors }
      end

      def id_hash(row)
        { 'id' => row.key & Frame::EFF_MASK, 'hex' => Frame.key_to_s(row.key),
          'extended' => row.key & Frame::EFF_FLAG != 0, 'frames' => row.frames }
      end

      def unclaimed_hash(row)
        id_hash(row).merge('first_time' => Report.seconds(row.first_time), 'last_time' => Report.seconds(row.last_time),
                           'write_only_matches' => row.writers, 'declared_by' => row.declared_by)
      end

      def device_hash(row)
        filter = row.can_filter
        filter &&= { 'id' => filter.id, 'mask' => filter.mask, 'extended' => filter.extended? }
        {
          'name' => row.name, 'status' => row.status.to_s, 'filter' => filter, 'frames' => row.frames,
          'distinct_ids' => row.keys.size, 'ids' => row.keys.map { |k| Frame.key_to_s(k) },
          'first_time' => Report.seconds(row.first_time), 'last_time' => Report.seconds(row.last_time),
          'rate' => row.rate&.round(3)
        }
      end
    end
  end
end
