# frozen_string_literal: true

require 'syskit/bus/frame'
require 'syskit/bus/traffic'
require 'syskit/can/timing/frame'

module Syskit
  module Bus
    # What a log shows of the traffic a plan declares on a bus (a
    # Network::Plan::Bus): per declared frame, how many were seen and their
    # mean and longest period; the declared frames never seen; the ids seen
    # but never declared; the load the log puts on the bus at the declared
    # bitrate. A value: renderers only read it. Times are Rational seconds.
    class DeclaredTraffic
      # A declared frame and what the log shows of it (periods are nil
      # below two frames). +late+: the longest period exceeds the declared
      # period plus jitter (a frame came late, or was lost).
      # +silent_for+: from its last frame to the end of the log; it fell
      # silent when that is longer than its period plus jitter (a gap the
      # log's end hides from +worst_period+).
      Row = Struct.new(:frame, :frames, :mean_period, :worst_period, :silent_for, keyword_init: true) do
        def late?
          !worst_period.nil? && worst_period > frame.period + frame.jitter
        end

        def silent_at_end?
          !silent_for.nil? && silent_for > frame.period + frame.jitter
        end
      end
      # An id seen but never declared.
      Unknown = Struct.new(:key, :frames)

      attr_reader :bus, :rows, :undeclared, :observed_load, :declared_load

      # +bus+: the plan's bus entry; +traffic+: the Traffic of the log.
      def initialize(bus, traffic)
        @bus = bus
        keys = bus.frames.map { |f| Frame.key(f.id, f.extended) }
        @rows = bus.frames.zip(keys).map { |f, key| row(f, traffic.ids[key], traffic.last_time) }
        declared = keys.to_h { |k| [k, true] }
        @undeclared = traffic.ids.keys.sort.reject { |k| declared[k] }.map { |k| Unknown.new(k, traffic.ids[k].frames) }
        @declared_load = bus.utilization
        @observed_load = load(traffic)
      end

      # The declared frames the log never shows.
      def unseen
        rows.select { |r| r.frames.zero? }
      end

      # As plain data, for --format json (times in seconds).
      def to_h
        {
          'bus' => bus.name, 'bitrate' => bus.bitrate,
          'declared_load' => declared_load&.to_f, 'observed_load' => observed_load&.to_f,
          'frames' => rows.map { |r| row_hash(r) },
          'unseen' => unseen.map { |r| Frame.key_to_s(Frame.key(r.frame.id, r.frame.extended)) },
          'undeclared' => undeclared.map { |u| { 'id' => Frame.key_to_s(u.key), 'frames' => u.frames } }
        }
      end

      private

      # The log's bits over its span, at the declared bitrate.
      def load(traffic)
        return unless bus.bitrate && traffic.first_time && traffic.last_time > traffic.first_time

        Rational(traffic.bits * 1_000_000, bus.bitrate * (traffic.last_time - traffic.first_time))
      end

      def row(frame, stats, log_end)
        return Row.new(frame: frame, frames: 0) unless stats

        silent_for = Rational(log_end - stats.last_time, 1_000_000) if log_end && stats.last_time
        unless stats.frames > 1 && stats.first_time
          return Row.new(frame: frame, frames: stats.frames,
                         silent_for: silent_for)
        end

        Row.new(frame: frame, frames: stats.frames,
                mean_period: Rational(stats.last_time - stats.first_time, 1_000_000 * (stats.frames - 1)),
                worst_period: Rational(stats.max_gap, 1_000_000), silent_for: silent_for)
      end

      def row_hash(row)
        f = row.frame
        { 'id' => Frame.key_to_s(Frame.key(f.id, f.extended)), 'device' => f.device, 'period' => f.period.to_f,
          'frames' => row.frames, 'mean_period' => row.mean_period&.to_f, 'worst_period' => row.worst_period&.to_f,
          'late' => row.late?, 'silent_at_end' => row.silent_at_end? ? row.silent_for.to_f : nil }
      end
    end
  end
end
