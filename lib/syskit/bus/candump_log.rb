# frozen_string_literal: true

require 'syskit/bus/frame'

module Syskit
  module Bus
    # Reads can-utils candump logs (`candump -l`, `candump -L`):
    #
    #   (1436509053.249713) can0 123#DEADBEEF
    #   (1436509053.250100) can0 12345678#00         extended id (8 digits)
    #   (1436509053.250200) can0 123#R               remote request (RTR)
    #   (1436509053.250300) can0 123#R4              RTR asking for 4 bytes
    #   (1436509053.250400) can0 123##1DEADBEEF      CAN FD, flags 1
    #   (1436509053.250500) can0 20000080#0000000000000000   error frame
    #
    # Lines logged from several interfaces have their names right-aligned
    # (padded with spaces); `candump -x` appends " R" or " T". Malformed
    # lines are counted and the first few kept with their line numbers,
    # never raised: a log cut short by a power failure must still replay.
    class CandumpLog
      # A line that is not a candump frame.
      Malformed = Struct.new(:lineno, :message, :text)
      # How many malformed lines are kept for the report.
      KEEP_MALFORMED = 5

      attr_reader :path, :interface, :interfaces, :malformed, :malformed_count, :lines

      # +interface+: the log interface whose frames are read; nil for the
      # interface of the first frame. Frames of other interfaces are counted
      # in #interfaces and skipped.
      def initialize(path, interface: nil)
        @path = path
        @interface = interface
        @interfaces = Hash.new(0)
        @malformed = []
        @malformed_count = 0
        @lines = 0
      end

      # Yields the Frame of every well-formed line of the selected
      # interface read from +io+.
      def each_frame(io)
        io.each_line do |line|
          @lines += 1
          frame, iface = parse_line(line)
          next unless frame

          @interface ||= iface
          @interfaces[iface] += 1
          yield frame if iface == @interface
        rescue ArgumentError => e
          add_malformed(@lines, e.message, line)
        end
        self
      end

      # Parses one line: [frame, interface], nil for a blank line. Raises
      # ArgumentError with a message for the user on a malformed line.
      def parse_line(line)
        line = line.chomp
        return if line.strip.empty?

        m = /\A\((\d+)\.(\d{1,9})\) +(\S+) (\S+)(?: [RT])?\z/.match(line)
        raise ArgumentError, "expected '(seconds.microseconds) interface frame', as candump -l writes" unless m

        [parse_frame(m[4], time_us(m[1], m[2])), m[3]]
      end

      # Parses the frame part of a line (+123#DEADBEEF+).
      def parse_frame(text, time = nil)
        id_text, rest = text.split('#', 2)
        raise ArgumentError, "no '#' after the id in '#{text}'" unless rest

        can_id = parse_id(id_text)
        return parse_rtr(can_id, rest[1..], time) if rest.start_with?('R', 'r')

        if rest.start_with?('#')
          raise ArgumentError, 'CAN XL frames (###) are not supported' if rest.start_with?('##')

          flags = rest[1]
          raise ArgumentError, "expected a hex digit of CAN FD flags after '##' in '#{text}'" unless flags&.match?(/\A\h\z/)

          return Frame.new(can_id: can_id, data: parse_data(rest[2..], Frame::CANFD_MAX_LEN, text),
                           time: time, fd_flags: flags.hex)
        end

        Frame.new(can_id: can_id, data: parse_data(rest, Frame::CAN_MAX_LEN, text), time: time)
      end

      private

      # Microseconds from the seconds and fraction digits, exactly.
      def time_us(seconds, fraction)
        (Integer(seconds, 10) * 1_000_000) + (fraction.ljust(6, '0')[0, 6].to_i)
      end

      def add_malformed(lineno, message, line)
        @malformed_count += 1
        @malformed << Malformed.new(lineno, message, line.chomp) if @malformed.size < KEEP_MALFORMED
      end

      def parse_id(text)
        unless text.match?(/\A(\h{3}|\h{8})\z/)
          raise ArgumentError, "bad id '#{text}': 3 hex digits for a standard frame, 8 for an extended one"
        end

        value = text.hex
        if text.size == 3
          raise ArgumentError, "standard id #{text} does not fit in 11 bits (at most 7FF)" if value > Frame::SFF_MASK

          return value
        end
        raise ArgumentError, "id #{text} has bits set beyond the 29-bit id and the error flag" if value > 0x3FFF_FFFF

        value & Frame::ERR_FLAG == 0 ? value | Frame::EFF_FLAG : value
      end

      def parse_rtr(can_id, rest, time)
        len_text = rest.split('_', 2).first.to_s
        len = len_text.empty? ? 0 : Integer(len_text, 10, exception: false)
        raise ArgumentError, "bad RTR length '#{len_text}': a digit from 0 to 8" unless len&.between?(0, Frame::CAN_MAX_LEN) && len_text.size <= 1

        Frame.new(can_id: can_id | Frame::RTR_FLAG, len: len, time: time)
      end

      def parse_data(text, max, frame_text)
        # len8_dlc (_9.._F): a classic frame of 8 bytes with a DLC above 8.
        text = text.sub(/_\h\z/, '') if max == Frame::CAN_MAX_LEN
        hex = text.delete('.')
        unless hex.match?(/\A(\h\h)*\z/)
          raise ArgumentError, "bad data '#{text}' in '#{frame_text}': pairs of hex digits expected"
        end

        len = hex.size / 2
        if len > max
          raise ArgumentError, "#{len} data bytes in '#{frame_text}': a CAN frame has at most 8 (CAN FD frames are written ID##FLAGSDATA)" if max == Frame::CAN_MAX_LEN

          raise ArgumentError, "#{len} data bytes in a CAN FD frame: at most 64"
        end
        if max == Frame::CANFD_MAX_LEN && !Frame::CANFD_LENGTHS.include?(len)
          raise ArgumentError, "a CAN FD frame cannot have #{len} data bytes (0-8, 12, 16, 20, 24, 32, 48 or 64)"
        end

        [hex].pack('H*')
      end
    end
  end
end
