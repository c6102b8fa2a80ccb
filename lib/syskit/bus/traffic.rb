# frozen_string_literal: true

require 'syskit/bus/frame'

module Syskit
  module Bus
    # Counts of the frames seen on a bus, per frame key (id + extended flag).
    #
    # Frames are counted per key and dispatched once per distinct key when
    # the report is built, not once per frame: every figure of the report
    # (per device frames, ids, first/last time; unclaimed and overlapping
    # ids) is a sum, min or max over keys.
    class Traffic
      # Frames of one key: how many, and the time of the first and last.
      IdStats = Struct.new(:count, :first, :last)

      attr_reader :ids, :frames, :extended, :fd, :rtr, :errors, :first_time, :last_time

      def initialize
        @ids = {}
        @frames = 0
        @extended = 0
        @fd = 0
        @rtr = 0
        @errors = 0
        @first_time = nil
        @last_time = nil
      end

      # Counts +frame+ (a Frame).
      def add(frame)
        @frames += 1
        time = frame.time
        if time
          @first_time = time if @first_time.nil? || time < @first_time
          @last_time = time if @last_time.nil? || time > @last_time
        end
        return @errors += 1 if frame.error?

        @extended += 1 if frame.extended?
        @fd += 1 if frame.fd?
        @rtr += 1 if frame.rtr?
        add_key(frame.key, time)
      end

      # Counts one frame of +key+ at +time+.
      def add_key(key, time)
        stats = @ids[key]
        if stats
          stats.count += 1
          stats.first = time if time && (stats.first.nil? || time < stats.first)
          stats.last = time if time && (stats.last.nil? || time > stats.last)
        else
          @ids[key] = IdStats.new(1, time, time)
        end
      end

      # Frames that are not error frames.
      def data_frames
        @frames - @errors
      end

      def standard
        data_frames - @extended
      end
    end
  end
end
