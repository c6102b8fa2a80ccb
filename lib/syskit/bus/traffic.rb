# frozen_string_literal: true

require 'syskit/bus/frame'
require 'syskit/can/timing/frame'

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
      # Frames of one key: how many, the time of the first and last, and
      # the longest time between two of them (in log order).
      IdStats = Struct.new(:frames, :first_time, :last_time, :max_gap)

      # Worst-case bits of a classic frame (see CAN::Timing::Frame#bits).
      STANDARD_BITS = CAN::Timing::Frame::STANDARD_BITS
      EXTENDED_BITS = CAN::Timing::Frame::EXTENDED_BITS
      BITS_PER_BYTE = CAN::Timing::Frame::BITS_PER_BYTE

      # The index of each figure in a tally (see #tallies).
      FRAMES = 0
      FIRST_TIME = 1
      LAST_TIME = 2
      MAX_GAP = 3

      attr_reader :frames, :extended, :fd, :rtr, :errors, :first_time, :last_time,
                  # Per key, [frames, first_time, last_time, max_gap] (the
                  # figures of IdStats, at the indexes above): arrays, which
                  # a log reader updates in place, without a call per frame
                  # (see CandumpLog#read and #add_totals).
                  :tallies

      def initialize
        @tallies = {}
        @ids = nil
        @frames = 0
        @extended = 0
        @fd = 0
        @rtr = 0
        @errors = 0
        @bytes = 0
        @fd_extended = 0
        @first_time = nil
        @last_time = nil
      end

      # Per key, its IdStats.
      def ids
        @ids ||= @tallies.transform_values { |tally| IdStats.new(*tally) }
      end

      # Adds the totals of frames a reader counted in #tallies itself, and
      # the span of their times (microseconds, nil when none).
      def add_totals(frames:, extended:, fd_frames:, fd_extended:, rtr:, errors:, bytes:, first_time:, last_time:)
        @ids = nil
        @frames += frames
        @extended += extended
        @fd += fd_frames
        @fd_extended += fd_extended
        @rtr += rtr
        @errors += errors
        @bytes += bytes
        span(first_time) if first_time
        span(last_time) if last_time
      end

      # Counts +frame+ (a Frame).
      def add(frame)
        return count_error(frame.time) if frame.error?

        count(frame.key, frame.time, frame.fd?, frame.rtr?, frame.rtr? ? 0 : frame.len)
      end

      # Counts one frame of +key+ (Frame.key) received at +time+
      # (microseconds, or nil) carrying +bytes+ data bytes.
      def count(key, time, fd_frame, rtr, bytes)
        @frames += 1
        extended = key >= Frame::EFF_FLAG
        @extended += 1 if extended
        if fd_frame
          @fd += 1
          @fd_extended += 1 if extended
        else
          @bytes += bytes
        end
        @rtr += 1 if rtr
        @ids = nil
        tally = @tallies[key]
        if tally
          tally[FRAMES] += 1
          stretch(tally, time) if time
        else
          @tallies[key] = [1, time, time, 0]
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

      # What the classic (not FD) data and remote frames took on the wire,
      # in bits, worst-case bit stuffing and inter-frame space included.
      # Counted from totals: a frame costs one addition of its data bytes.
      def bits
        classic_extended = @extended - @fd_extended
        classic_standard = data_frames - @fd - classic_extended
        (STANDARD_BITS * classic_standard) + (EXTENDED_BITS * classic_extended) + (BITS_PER_BYTE * @bytes)
      end

      # Same as #span, for the times of one key's tally; public for the log
      # readers that update tallies themselves (see CandumpLog#read).
      def stretch(tally, time)
        # Logs are in time order: the last frame is the latest, except in
        # logs merged from several sources.
        last = tally[LAST_TIME]
        if last.nil? then tally[FIRST_TIME] = tally[LAST_TIME] = time
        elsif time >= last
          gap = time - last
          tally[MAX_GAP] = gap if gap > tally[MAX_GAP]
          tally[LAST_TIME] = time
        elsif time < tally[FIRST_TIME] then tally[FIRST_TIME] = time
        end
      end

      private

      def span(time)
        if @last_time.nil? then @first_time = @last_time = time
        elsif time >= @last_time then @last_time = time
        elsif time < @first_time then @first_time = time
        end
      end
    end
  end
end
