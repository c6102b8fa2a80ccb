# frozen_string_literal: true

require 'syskit/can/timing/frame'

module Syskit
  module Robot
    # The CAN traffic a robot declares, for the timing analysis: the bitrate
    # of each CAN bus and the frames each attached device puts on it:
    #
    #   com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(500_000)
    #   through 'can0' do
    #     device(Devices::Motor, as: 'left').frame(0x181, bytes: 8, period: 0.001)
    #   end
    #
    # Any bus whose message type is /canbus/Message is a CAN bus (the
    # bundled model, a real common_models one, a bus that provides either).
    # A CAN bus attached to a CAN bus (a demultiplexer such as NMEA 2000)
    # shares its wire: its devices' frames count on the bus it is attached
    # to, which carries the bitrate.
    module CanTraffic
      MESSAGE_TYPE = '/canbus/Message'
      # Above this utilisation `syskit check` warns, unless the bus says otherwise.
      DEFAULT_WARN_ABOVE = 0.7r
      # Classic CAN runs at 1 Mbit/s at most.
      MAX_BITRATE = 1_000_000
      NO_FRAMES = [].freeze

      # Whether +bus+ is a bus of CAN frames.
      def self.can_bus?(bus)
        return false unless bus.respond_to?(:com_bus?) && bus.com_bus?

        type = bus.model.message_type
        !type.nil? && type.name == MESSAGE_TYPE
      end

      # The +frame+ statement of devices attached to a CAN bus.
      module DeviceStatements
        # Declares a frame this device's traffic puts on its CAN bus (sent
        # by the device, or by the host to it): its identifier, data bytes
        # (0-8), period, and optionally deadline (default: the period),
        # queuing jitter (default 0), all in seconds, and extended: (default:
        # whether the identifier exceeds 0x7FF).
        def frame(id = nil, bytes: nil, period: nil, deadline: nil, jitter: 0, extended: nil, **others)
          location = Location.of_caller
          check_frame_options(others, location)
          check_frame_declaration(id, bytes, period, location)
          frame = CAN::Timing::Frame.build(id: id, bytes: bytes, period: period, deadline: deadline, jitter: jitter,
                                           extended: extended, device: name, location: location)
          (@can_frames ||= []) << frame
          self
        rescue CAN::Timing::InvalidFrame => e
          raise DeclarationError.new("frame(#{id.inspect}, ...) on #{self}: #{e.message}",
                                     location: location, hint: e.hint)
        end

        # The frames declared with #frame, in declaration order.
        def can_frames
          @can_frames || NO_FRAMES
        end

        FRAME_OPTIONS = %w[bytes period deadline jitter extended].freeze
        private_constant :FRAME_OPTIONS

        private

        def check_frame_options(others, location)
          return if others.empty?

          unknown = others.keys.first.to_s
          raise DeclarationError.new(
            "frame on #{self} has no option #{unknown}:#{Naming.did_you_mean(unknown, FRAME_OPTIONS)}",
            location: location,
            hint: 'frame takes (id, bytes:, period:, deadline: period, jitter: 0, extended: id > 0x7FF)'
          )
        end

        def check_frame_declaration(id, bytes, period, location)
          unless CanTraffic.can_bus?(bus)
            where = attached? ? "#{bus}, whose messages are not #{MESSAGE_TYPE}" : 'no bus'
            raise DeclarationError.new(
              "#{self} is attached to #{where}: frame is for devices on a CAN bus",
              location: location,
              hint: "declare #{name} in a through 'can0' do ... end block of a CAN bus " \
                    '(or call attach_to before frame)'
            )
          end
          missing = { 'the identifier' => id, 'bytes:' => bytes, 'period:' => period }.select { |_, v| v.nil? }.keys
          return if missing.empty?

          raise DeclarationError.new("frame on #{self} needs #{missing.join(', ')}",
                                     location: location, hint: 'write frame(0x181, bytes: 8, period: 0.01)')
        end
      end

      # The +bitrate+ statement of CAN buses, and the frames on their wire.
      module BusStatements
        # Without arguments, the bitrate (bit/s, nil when not declared).
        # With them, declares it, and optionally the utilisation above which
        # `syskit check` warns (a fraction, 0.7 by default); returns the bus.
        def bitrate(bits_per_second = nil, warn_above: nil, **others)
          return @bitrate if bits_per_second.nil? && warn_above.nil? && others.empty?

          location = Location.of_caller
          unless others.empty?
            raise DeclarationError.new("bitrate on #{self} has no option #{others.keys.first}:",
                                       location: location,
                                       hint: 'write bitrate(500_000) or bitrate(500_000, warn_above: 0.6)')
          end
          check_bitrate_declaration(bits_per_second, location)
          @warn_above = warn_above_fraction(warn_above, location) unless warn_above.nil?
          @bitrate = bits_per_second
          @bitrate_location = location
          self
        end

        # Where the bitrate was declared.
        attr_reader :bitrate_location

        # The utilisation above which `syskit check` warns.
        def warn_above
          @warn_above || DEFAULT_WARN_ABOVE
        end

        # The CAN bus whose wire this bus's frames travel on: the outermost
        # CAN bus it is attached through, or itself.
        def carrier
          outer = self
          outer = outer.bus while CanTraffic.can_bus?(outer.bus)
          outer
        end

        # Every frame on this bus's wire: its devices', and those of the
        # devices of CAN buses attached to it, in declaration order.
        def frames_on_wire
          each_attached_device.flat_map do |device|
            # (flat_map takes each device's own array as it is)
            if device.com_bus? && CanTraffic.can_bus?(device)
              device.can_frames + device.frames_on_wire
            else
              device.can_frames
            end
          end
        end

        private

        def check_bitrate_declaration(bits_per_second, location)
          what = bitrate_problem(bits_per_second)
          raise DeclarationError.new("bitrate on #{self}: #{what.first}", location: location, hint: what.last) if what
        end

        # [message, hint], or nil for a bitrate this bus can have.
        def bitrate_problem(value)
          if !CanTraffic.can_bus?(self)
            ["#{model} does not carry #{MESSAGE_TYPE} frames", 'bitrate is for CAN buses']
          elsif CanTraffic.can_bus?(bus)
            ["#{name} is attached to #{bus}: its frames travel on #{carrier.name}'s wire",
             "declare the bitrate of #{carrier.name}"]
          elsif !value.is_a?(Integer) || !value.between?(1, MAX_BITRATE)
            ["#{value.inspect} is not a CAN bitrate",
             'bitrate takes bits per second, an integer up to 1_000_000 (classic CAN): write bitrate(500_000)']
          end
        end

        def warn_above_fraction(value, location)
          fraction = value.is_a?(Float) && value.finite? ? Rational(value.to_s) : value
          return fraction.to_r if fraction.is_a?(Numeric) && !fraction.is_a?(Complex) && fraction.positive? &&
                                  fraction <= 1

          raise DeclarationError.new("warn_above: #{value.inspect} on #{self} is not a fraction of the bus",
                                     location: location, hint: 'warn_above: takes a fraction, e.g. 0.6 for 60 %')
        end

        def chainable_methods
          super + %w[bitrate]
        end
      end
    end
  end
end
