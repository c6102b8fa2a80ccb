# frozen_string_literal: true

require 'syskit/can'

module Syskit
  module CAN
    # Worst-case timing of CAN buses (see syskit/can/timing.rb).
    module Timing
      # A declared value the analysis cannot use; +hint+ says what to write.
      class InvalidFrame < ArgumentError
        attr_reader :hint

        def initialize(message, hint)
          super(message)
          @hint = hint
        end
      end

      # One frame that some device's traffic puts on a CAN bus, queued at
      # most every +period+ seconds, at most +jitter+ seconds after its
      # release, due +deadline+ seconds after its release. Times are exact
      # (Rational seconds). +device+ and +location+ say where it was
      # declared, for reports: the analysis never reads them.
      Frame = Struct.new(:id, :extended, :bytes, :period, :deadline, :jitter, :device, :location,
                         keyword_init: true)

      # Frame lengths, arbitration order and checked construction.
      class Frame
        MAX_BYTES = 8
        # Bits of a frame without data, worst-case bit stuffing and the
        # 3-bit inter-frame space included; each data byte adds 10 (8, and
        # 2 stuff bits at worst). These are Davis et al.'s
        # g + 8s + 13 + floor((g + 8s - 1) / 4) with g = 34 and g = 54,
        # which equal 55 + 10s and 80 + 10s for every s in 0..8.
        STANDARD_BITS = 55
        EXTENDED_BITS = 80
        BITS_PER_BYTE = 10
        # An extended identifier is 11 base bits then 18 extension bits.
        EXTENSION_BITS = 18
        EXTENSION_MASK = (1 << EXTENSION_BITS) - 1

        # A frame from the values a user declares, checked; raises
        # InvalidFrame. Times are seconds: Integer, Float (read as the
        # decimal written, 0.001 is 1/1000) or Rational.
        def self.build(id:, bytes:, period:, deadline: nil, jitter: 0, extended: nil, device: nil, location: nil)
          check_id(id, extended)
          extended = id > STANDARD_ID_MAX if extended.nil?
          check_bytes(bytes)
          period = Timing.seconds(period, 'period', positive: true)
          deadline = deadline.nil? ? period : Timing.seconds(deadline, 'deadline', positive: true)
          jitter = Timing.seconds(jitter, 'jitter', positive: false)
          new(id: id, extended: extended, bytes: bytes, period: period, deadline: deadline, jitter: jitter,
              device: device, location: location).freeze
        end

        def self.check_id(id, extended)
          unless id.is_a?(Integer) && id.between?(0, EXTENDED_ID_MAX)
            raise InvalidFrame.new("the identifier #{id.inspect} is not a CAN identifier",
                                   'CAN identifiers are integers of 11 bits (standard, up to 0x7FF) ' \
                                   'or 29 bits (extended, up to 0x1FFFFFFF)')
          end
          unless [nil, true, false].include?(extended)
            raise InvalidFrame.new("extended: takes true or false, got #{extended.inspect}",
                                   'leave extended: out: ids above 0x7FF are extended, the others standard')
          end
          return unless extended == false && id > STANDARD_ID_MAX

          raise InvalidFrame.new(format('the identifier 0x%X does not fit in 11 bits (extended: false)', id),
                                 'drop extended: false, or give a standard identifier (at most 0x7FF)')
        end

        def self.check_bytes(bytes)
          return if bytes.is_a?(Integer) && bytes.between?(0, MAX_BYTES)

          raise InvalidFrame.new("bytes: #{bytes.inspect} is not a CAN data length",
                                 'bytes: takes 0 to 8, the data bytes of a classic CAN frame')
        end

        # Bits on the wire in the worst case.
        def bits
          (extended ? EXTENDED_BITS : STANDARD_BITS) + (BITS_PER_BYTE * bytes)
        end

        # Lower wins arbitration. CAN 2.0B compares the 11 base bits first;
        # then a standard frame's dominant RTR bit beats an extended
        # frame's recessive SRR bit; then the 18 extension bits.
        def arbitration_key
          return id << (EXTENSION_BITS + 1) unless extended

          ((id >> EXTENSION_BITS) << (EXTENSION_BITS + 1)) | (1 << EXTENSION_BITS) | (id & EXTENSION_MASK)
        end

        # The identifier as candump writes it: 3 hex digits, or 8 for an
        # extended one.
        def hex_id
          extended ? format('%08X', id) : format('%03X', id)
        end

        def to_s
          "frame 0x#{hex_id}"
        end
      end

      module_function

      # The share of the bus +frames+ take at +bitrate+ (sum of C/T), exact.
      def utilization(bitrate, frames)
        frames.sum(0r) { |f| Rational(f.bits, bitrate) / f.period }
      end

      # +value+ seconds as an exact Rational; raises InvalidFrame.
      def seconds(value, what, positive:)
        exact = case value
                when Integer, Rational then value.to_r
                when Float then Rational(value.to_s) if value.finite?
                end
        return exact if exact && (positive ? exact.positive? : !exact.negative?)

        raise InvalidFrame.new("#{what}: #{value.inspect} is not a #{positive ? 'positive' : 'non-negative'} " \
                               'number of seconds',
                               "#{what}: takes seconds, e.g. #{what}: 0.01 for 10 ms")
      end
    end
  end
end
