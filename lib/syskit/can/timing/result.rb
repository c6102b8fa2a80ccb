# frozen_string_literal: true

module Syskit
  module CAN
    module Timing
      # The analysis of one frame; times are Rational seconds.
      # +response_time+ is nil when the frame's priority level is loaded 100 %
      # or more (no bound); +original_response_time+ is what the 1994
      # analysis gives (the first instance of the busy period only);
      # +worst_instance+ is the q of the instance with the worst response,
      # +instances+ the instances of the busy period examined (Q_m, or
      # fewer when the later ones cannot respond later, see Analysis).
      # +stopped_at_miss+: the analysis stopped at the first instance that
      # misses its deadline, before others that could respond later:
      # +response_time+ is then a lower bound of the worst case.
      FrameResult = Struct.new(:frame, :transmission_time, :blocking, :response_time, :original_response_time,
                               :worst_instance, :instances, :stopped_at_miss, keyword_init: true) do
        # Whether the frame always arrives before its deadline.
        def schedulable?
          !response_time.nil? && response_time <= frame.deadline
        end

        # Deadline minus worst-case response time (negative when missed, nil
        # when unbounded).
        def slack
          response_time && (frame.deadline - response_time)
        end

        # The JSON entry of `syskit bus timing`, times in seconds;
        # +response_time+ is null for a frame that can miss its deadline
        # (+slack+ then says by how much, when bounded: at least by that
        # much when +stopped_at_miss+).
        def to_h
          f = frame
          {
            'id' => f.id, 'extended' => f.extended, 'bytes' => f.bytes, 'device' => f.device,
            'period' => f.period.to_f, 'deadline' => f.deadline.to_f, 'jitter' => f.jitter.to_f,
            'transmission_time' => transmission_time.to_f, 'blocking' => blocking.to_f,
            'response_time' => schedulable? ? response_time.to_f : nil, 'slack' => slack&.to_f,
            'schedulable' => schedulable?, 'stopped_at_miss' => stopped_at_miss
          }
        end
      end

      # The analysis of a bus: its frames in priority order and its
      # utilisation (sum of C/T, a Rational).
      BusResult = Struct.new(:bitrate, :utilization, :frames, keyword_init: true) do
        # Whether the bus is loaded 100 % or more: the lowest frames then
        # have no bound.
        def overloaded?
          utilization >= 1
        end

        # Whether every frame always arrives before its deadline.
        def schedulable?
          !overloaded? && frames.all?(&:schedulable?)
        end

        # The frames that can miss their deadline.
        def misses
          frames.reject(&:schedulable?)
        end

        # The JSON document of `syskit bus timing` (+bus+: the bus's name).
        def to_h(bus)
          { 'bus' => bus, 'bitrate' => bitrate, 'utilization' => utilization.to_f, 'schedulable' => schedulable?,
            'frames' => frames.map(&:to_h) }
        end
      end
    end
  end
end
