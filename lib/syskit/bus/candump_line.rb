# frozen_string_literal: true

require 'syskit/bus/frame'

module Syskit
  module Bus
    # The full parser of one candump log line, with a message for the user
    # on each way a line can be wrong. CandumpLog reads well-formed lines
    # faster itself and only calls this one for the others.
    #
    #   (1436509053.249713) can0 123#DEADBEEF         standard id (3 digits)
    #   (1436509053.250100) can0 12345678#00          extended id (8 digits)
    #   (1436509053.250200) can0 123#R                remote request (RTR)
    #   (1436509053.250300) can0 123#R4               RTR asking for 4 bytes
    #   (1436509053.250400) can0 123##1DEADBEEF       CAN FD, flags 1
    #   (1436509053.250500) can0 20000080#0000000000000000   error frame
    #
    # Also accepted, as can-utils writes or reads them: interface names
    # padded with spaces (logs of several interfaces), a trailing " R" or
    # " T" (candump -x), '.' between data bytes, a len8_dlc suffix (_9.._F)
    # and CRLF line ends.
    module CandumpLine
      # What a malformed line raises; its message is for the user.
      class Malformed < StandardError; end

      LINE = /\A\((\d+)\.(\d{1,9})\) +(\S+) (\S+)(?: [RT])?\z/

      module_function

      # [frame, interface] for a line; nil for a blank line.
      def parse(line)
        line = line.chomp
        return if line.strip.empty?

        m = LINE.match(line)
        raise Malformed, "expected '(seconds.microseconds) interface frame', as candump -l writes" unless m

        [parse_frame(m[4], time_us(m[1], m[2])), m[3]]
      end

      # The Frame of the frame part of a line (+123#DEADBEEF+).
      def parse_frame(text, time = nil)
        id_text, rest = text.split('#', 2)
        raise Malformed, "no '#' after the id in '#{text}'" unless rest

        can_id = parse_id(id_text)
        return parse_rtr(can_id, rest[1..], time) if rest.start_with?('R', 'r')
        return parse_fd(can_id, rest[1..], text, time) if rest.start_with?('#')

        Frame.new(can_id: can_id, data: parse_data(rest, Frame::CAN_MAX_LEN, text), time: time)
      end

      # Microseconds from the seconds and fraction digits, exactly.
      def time_us(seconds, fraction)
        (Integer(seconds, 10) * 1_000_000) + fraction.ljust(6, '0')[0, 6].to_i
      end

      def parse_id(text)
        unless text.match?(/\A(\h{3}|\h{8})\z/)
          raise Malformed, "bad id '#{text}': 3 hex digits for a standard frame, 8 for an extended one"
        end

        value = text.hex
        if text.size == 3
          raise Malformed, "standard id #{text} does not fit in 11 bits (at most 7FF)" if value > Frame::SFF_MASK

          return value
        end
        raise Malformed, "id #{text} has bits set beyond the 29-bit id and the error flag" if value > 0x3FFF_FFFF

        (value & Frame::ERR_FLAG).zero? ? value | Frame::EFF_FLAG : value
      end

      def parse_rtr(can_id, rest, time)
        len_text = rest.split('_', 2).first.to_s
        len = len_text.empty? ? 0 : Integer(len_text, 10, exception: false)
        unless len&.between?(0, Frame::CAN_MAX_LEN) && len_text.size <= 1
          raise Malformed, "bad RTR length '#{len_text}': a digit from 0 to 8"
        end

        Frame.new(can_id: can_id | Frame::RTR_FLAG, len: len, time: time)
      end

      def parse_fd(can_id, rest, text, time)
        raise Malformed, 'CAN XL frames (###) are not supported' if rest.start_with?('#')

        flags = rest[0]
        raise Malformed, "expected a hex digit of CAN FD flags after '##' in '#{text}'" unless flags&.match?(/\A\h\z/)

        Frame.new(can_id: can_id, data: parse_data(rest[1..], Frame::CANFD_MAX_LEN, text), time: time,
                  fd_flags: flags.hex)
      end

      def parse_data(text, max, frame_text)
        # len8_dlc (_9.._F): a classic frame of 8 bytes with a DLC above 8.
        text = text.sub(/_\h\z/, '') if max == Frame::CAN_MAX_LEN
        hex = text.delete('.')
        unless hex.match?(/\A(\h\h)*\z/)
          raise Malformed,
                "bad data '#{text}' in '#{frame_text}': pairs of hex digits expected"
        end

        len = hex.size / 2
        check_length(len, max, frame_text)
        [hex].pack('H*')
      end

      def check_length(len, max, frame_text)
        if max == Frame::CAN_MAX_LEN
          return if len <= max

          raise Malformed, "#{len} data bytes in '#{frame_text}': a CAN frame has at most 8 " \
                           '(CAN FD frames are written ID##FLAGSDATA)'
        end
        return if Frame::CANFD_LENGTHS.include?(len)

        raise Malformed, "a CAN FD frame cannot have #{len} data bytes (0-8, 12, 16, 20, 24, 32, 48 or 64)"
      end
    end
  end
end
