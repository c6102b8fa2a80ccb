# frozen_string_literal: true

require 'syskit/bus/frame'

module Syskit
  module Bus
    # Counts of the frames seen on a bus, per frame key (Frame.key: id +
    # extended flag).
    #
    # Frames are counted per key and dispatched once per distinct key when
    # the report is built, not once per frame: every figure of the report
    # (per device frames, ids, first/last time; unclaimed and overlapping
    # ids) is a sum, min or max over keys. Times are in microseconds.
    class Traffic
      # Frames of one key: how many, and the time of the first and last.
      IdStats = Struct.new(:frames, :first_time, :last_time)

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
        return count_error(frame.time) if frame.error?

        count(frame.key, frame.time, frame.extended?, frame.fd?, frame.rtr?)
      end

      # Counts one frame of +key+ received at +time+ (microseconds, or nil).
      def count(key, time, extended, fd_frame, rtr)
        @frames += 1
        @extended += 1 if extended
        @fd += 1 if fd_frame
        @rtr += 1 if rtr
        stats = @ids[key]
        if stats
          stats.frames += 1
          stretch(stats, time) if time
        else
          @ids[key] = IdStats.new(1, time, time)
        end
        span(time) if time
      end

      # Counts an error frame: in the totals, never dispatched.
      def count_error(time)
        @frames += 1
        @errors += 1
        span(time) if time
      end

      # Frames that are not error frames.
      def data_frames
        @frames - @errors
      end

      def standard
        data_frames - @extended
      end

      private

      # Same as #span, for the times of one key.
      def stretch(stats, time)
        # Logs are in time order: the last frame is the latest, except in
        # logs merged from several sources.
        if stats.last_time.nil? then stats.first_time = stats.last_time = time
        elsif time >= stats.last_time then stats.last_time = time
        elsif time < stats.first_time then stats.first_time = time
        end
      end

      def span(time)
        if @last_time.nil? then @first_time = @last_time = time
        elsif time >= @last_time then @last_time = time
        elsif time < @first_time then @first_time = time
        end
      end
    end
  end
end
