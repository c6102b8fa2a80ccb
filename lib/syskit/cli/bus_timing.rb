# frozen_string_literal: true

require 'syskit/can/timing'
require 'syskit/can/timing/table'

module Syskit
  class CLI < Thor
    # What `syskit bus timing` does between parsing its options and
    # printing: find the bus, analyse it, render the result.
    module BusTiming
      module_function

      # [BusResult, bus] of the CAN bus +name+ of +profile+'s robot (the
      # only CAN bus with declared traffic when +name+ is nil).
      def analyse(profile, name)
        bus = name ? named_bus(profile, name) : only_bus(profile)
        unless bus.bitrate
          raise Error.new("#{bus} has no bitrate: its frames cannot be timed",
                          location: bus.declared_at,
                          hint: "declare it: com_bus(..., as: '#{bus.name}').bitrate(500_000)")
        end

        [CAN::Timing::Analysis.run(bitrate: bus.bitrate, frames: bus.frames_on_wire), bus]
      end

      # The result as the JSON document or the table.
      def render(result, bus, profile, format)
        if format == 'json'
          require 'syskit/render/json'
          ::Syskit::Render::JSON.pretty(result.to_h(bus.name))
        else
          CAN::Timing::Table.render(result, "Bus #{bus.name} of #{profile.name}")
        end
      end

      # [bus, frames that can miss their deadline, frames] of each CAN bus of
      # the profile's robot where some can (declaration order).
      def missed_deadlines(profile)
        can_buses(profile).filter_map do |bus|
          next unless bus.bitrate

          frames = bus.frames_on_wire
          missed = CAN::Timing::Analysis.run(bitrate: bus.bitrate, frames: frames).frames.count { |r| !r.schedulable? }
          [bus, missed, frames.size] if missed.positive?
        end
      end

      # The CAN buses of the profile's robot with a wire of their own.
      def can_buses(profile)
        profile.robot.each_master_device.grep(Robot::ComBus).select { |b| Robot::CanTraffic.can_bus?(b) && b.carrier.equal?(b) }
      end

      # The bus +name+, or an error saying which buses can be timed.
      def named_bus(profile, name)
        bus = profile.robot.find_device(name)
        return bus if bus.is_a?(Robot::ComBus) && Robot::CanTraffic.can_bus?(bus) && bus.carrier.equal?(bus)

        if bus.is_a?(Robot::ComBus) && Robot::CanTraffic.can_bus?(bus)
          raise UnknownName.new("#{bus} is attached to #{bus.bus}: its frames travel on #{bus.carrier.name}'s wire",
                                hint: "time that bus: --bus #{bus.carrier.name}")
        end
        names = can_buses(profile).map(&:name)
        what = bus ? "#{bus} is not a CAN bus" : "#{profile.name} has no bus named '#{name}'"
        raise UnknownName.new("#{what}#{Naming.did_you_mean(name, names)}", hint: buses_hint(names))
      end

      # The only CAN bus that declares traffic (or the only CAN bus).
      def only_bus(profile)
        buses = can_buses(profile)
        declared = buses.select { |b| b.bitrate || b.frames_on_wire.any? }
        candidates = declared.empty? ? buses : declared
        return candidates.first if candidates.size == 1

        what = candidates.empty? ? 'no CAN bus' : 'several CAN buses'
        raise UnknownName.new("#{profile.name} has #{what}", hint: buses_hint(candidates.map(&:name)))
      end

      # What to write for --bus.
      def buses_hint(names)
        return 'declare one: com_bus(CommonModels::Devices::Bus::CAN, as: \'can0\').bitrate(500_000)' if names.empty?

        "choose one with --bus (#{names.join(', ')})"
      end
    end
  end
end
