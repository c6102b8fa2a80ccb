# frozen_string_literal: true

require 'syskit/can/timing'

module Syskit
  module Checks
    # `syskit check`'s CAN timing problems of a profile's robot, per CAN bus
    # that carries declared traffic (see Robot::CanTraffic):
    # - errors: a frame that can miss its deadline, a bus loaded 100 % or
    #   more, one identifier declared twice on a bus;
    # - warnings: a bus loaded above its warn_above level (70 % by default),
    #   frames on a bus without a bitrate.
    class CanTiming
      def initialize(profile)
        @profile = profile
      end

      # The problems found, bus by bus in declaration order.
      def problems
        @profile.robot.each_master_device.grep(Robot::ComBus).flat_map do |bus|
          next [] unless Robot::CanTraffic.can_bus?(bus) && bus.carrier.equal?(bus)

          bus_problems(bus, bus.frames_on_wire)
        end
      end

      private

      def bus_problems(bus, frames)
        problems = duplicates(bus, frames)
        if bus.bitrate
          problems + timing_problems(bus, CAN::Timing::Analysis.run(bitrate: bus.bitrate, frames: frames))
        elsif frames.any?
          problems << no_bitrate(bus, frames)
        else
          problems
        end
      end

      # One error per frame whose identifier an earlier frame of the bus has.
      def duplicates(bus, frames)
        first = {}
        frames.filter_map do |frame|
          earlier = first[frame.arbitration_key]
          next duplicate(bus, earlier, frame) if earlier

          first[frame.arbitration_key] = frame
          nil
        end
      end

      def duplicate(bus, earlier, frame)
        why = if earlier.device == frame.device
                "twice by #{frame.device} on #{bus}: each identifier is one frame of the bus"
              else
                "by #{earlier.device} and #{frame.device} on #{bus}: two senders of one identifier break CAN " \
                  'arbitration'
              end
        TimingError.new(
          "#{frame} is declared #{why} (the first is declared at #{earlier.location})",
          location: frame.location, hint: 'give each frame of a bus its own identifier'
        )
      end

      def timing_problems(bus, result)
        problems = result.frames.select { |r| r.response_time && !r.schedulable? }.map { |r| miss(bus, r) }
        if result.overloaded?
          problems << overload(bus, result)
        elsif result.utilization > bus.warn_above
          problems << high_load(bus, result)
        end
        problems
      end

      def miss(bus, result)
        frame = result.frame
        at_least = result.stopped_at_miss ? 'at least ' : ''
        TimingError.new(
          "#{frame} of #{frame.device} on #{bus} can miss its deadline: worst-case response time #{at_least}" \
          "#{CAN::Timing::Format.ms(result.response_time)}, deadline #{CAN::Timing::Format.ms(frame.deadline)}",
          location: frame.location, hint: miss_hint(bus, result)
        )
      end

      def miss_hint(bus, result)
        frame = result.frame
        if frame.jitter + result.transmission_time > frame.deadline
          "its jitter alone (#{CAN::Timing::Format.ms(frame.jitter)}, plus its own transmission) is past its " \
            'deadline: declare the jitter it has (seconds: jitter: 0.0005 is 0.5 ms) or a later deadline'
        else
          'give it a lower identifier (a higher priority), a later deadline or fewer bytes, or lower the ' \
            "bus's load; #{command(bus)} shows every frame"
        end
      end

      def overload(bus, result)
        unbounded = result.frames.reject(&:response_time)
        TimingError.new(
          "#{bus} is loaded #{CAN::Timing::Format.percent(result.utilization)} at " \
          "#{CAN::Timing::Format.bitrate(bus.bitrate)}: #{unbounded.size} of its frames (from " \
          "0x#{unbounded.first.frame.hex_id} down) have no bounded response time",
          location: bus.bitrate_location,
          hint: 'a CAN bus carries less than 100 %: raise the bitrate, lengthen periods or move frames to another bus'
        )
      end

      def high_load(bus, result)
        Warning.new(
          "#{bus} is loaded #{CAN::Timing::Format.percent(result.utilization)}, above its warning level of " \
          "#{CAN::Timing::Format.percent(bus.warn_above)}",
          location: bus.bitrate_location,
          hint: 'lower the load, or raise the level if it is meant: ' \
                "bitrate(#{bus.bitrate}, warn_above: 0.8); #{command(bus)} shows every frame"
        )
      end

      def no_bitrate(bus, frames)
        Warning.new(
          "#{bus} carries #{frames.size} declared #{frames.size == 1 ? 'frame' : 'frames'} but has no bitrate: " \
          'their timing is not checked',
          location: bus.declared_at,
          hint: "declare it: com_bus(..., as: '#{bus.name}').bitrate(500_000)"
        )
      end

      def command(bus)
        "syskit bus timing #{@profile.name} --bus #{bus.name}"
      end
    end
  end
end
