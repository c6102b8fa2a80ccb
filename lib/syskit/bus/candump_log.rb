# frozen_string_literal: true

require 'syskit/bus/frame'
require 'syskit/bus/candump_line'

module Syskit
  module Bus
    # Reads can-utils candump logs (`candump -l`, `candump -L`; see
    # CandumpLine for the format) into a Traffic.
    #
    # Malformed lines are counted and the first few kept with their line
    # numbers, never raised: a log cut short by a power failure must still
    # replay. Frames of other interfaces than the one read are counted per
    # interface and skipped.
    class CandumpLog
      # A line that is not a candump frame.
      Malformed = Struct.new(:lineno, :message, :text)
      # The first line whose time is before the line read before it (a log
      # merged from several, a clock set back), and how many such lines.
      Backwards = Struct.new(:lineno, :time, :previous_time, :lines)
      # How many malformed lines are kept for the report.
      KEEP_MALFORMED = 5
      # A line as candump writes it, checked whole without captures (no
      # allocation): lines that pass are read by index arithmetic, the
      # others (rare: malformed or unusual spellings) by CandumpLine.
      WRITTEN = /\A\(\d+\.\d{6}\) +[^ \n]+ (?:\h{3}|\h{8})#(?:R[0-8]?|#\h(?:\h\h){0,64}|(?:\h\h){0,8})(?: [RT])?\n?\z/
      # The longest line candump writes is under 300 bytes (a CAN FD frame
      # of 64 bytes). Lines are read in pieces of at most this many bytes, a
      # longer line is skipped piece by piece: memory stays bounded whatever
      # the file holds (a binary file, /dev/zero).
      MAX_LINE = 4096
      SPACE = 32
      FD_MARK = 35 # '#'
      RTR_MARK = 82 # 'R'

      # +backwards+: a Backwards when the log is not in time order, else nil.
      attr_reader :path, :interface, :other_interfaces, :malformed, :malformed_count, :lines, :backwards

      # +interface+: the log interface whose frames are read; nil for the
      # interface of the first frame.
      def initialize(path, interface: nil)
        @path = path
        # Compared with the log's bytes.
        @interface = interface&.b
        @other_interfaces = Hash.new(0)
        @malformed = []
        @malformed_count = 0
        @lines = 0
        @previous_time = nil
        @backwards = nil
      end

      # Counts every frame of the selected interface read from +io+ into
      # +traffic+ (a Traffic); yields after each line, for progress.
      def read(io, traffic)
        each_line(io) do |line|
          count_written(line, traffic) || count_parsed(line, traffic) if line
          yield if block_given?
        end
        self
      end

      # Yields the Frame of every well-formed line of the selected interface
      # read from +io+ (slower than #read: for programs that want frames).
      def each_frame(io)
        each_line(io) do |line|
          next unless line

          frame, iface = parse(line)
          yield frame if frame && selected?(iface)
        end
        self
      end

      private

      # Yields each line of +io+, counting them; a line longer than MAX_LINE
      # is counted as malformed and its pieces yielded as nil (for progress).
      def each_line(io)
        long = false
        io.each_line(MAX_LINE) do |piece|
          whole = piece.bytesize < MAX_LINE || piece.end_with?("\n")
          unless long
            @lines += 1
            too_long(piece) unless whole
          end
          yield(long || !whole ? nil : piece)
          long = !whole
        end
      end

      def too_long(piece)
        record_malformed("longer than #{MAX_LINE} bytes, which no candump line is: is this a candump log?",
                         "#{piece.byteslice(0, 40).inspect}...")
      end

      # Counts a line that matched WRITTEN, reading its fields by position;
      # false when its values need CandumpLine's checks and messages. One
      # method on purpose: it runs for every line of logs of millions, and
      # every call and string made here shows in the replay's speed.
      # rubocop:disable-next Metrics/AbcSize, Metrics/CyclomaticComplexity, Metrics/PerceivedComplexity -- one method, see above
      def count_written(line, traffic)
        return false unless line.match?(WRITTEN)

        close = line.index(')')
        # The id is the 3 or 8 digits before the first '#' after the time.
        hash = line.index('#', close)
        extended = line.getbyte(hash - 4) != SPACE
        id_start = extended ? hash - 8 : hash - 3
        id = line.byteslice(id_start, hash - id_start).to_i(16)
        return false if id > (extended ? 0x3FFF_FFFF : Frame::SFF_MASK)

        mark = line.getbyte(hash + 1)
        fd = mark == FD_MARK
        bytes = 0 # a remote request carries none
        if fd
          bytes = fd_length(line, hash)
          return false unless Frame::CANFD_LENGTHS.include?(bytes)
        elsif mark != RTR_MARK
          # Half the characters after #, whether an end of line follows or
          # not; one less when the " R"/" T" flags of candump -x do.
          bytes = (line.bytesize - hash - 1) >> 1
          bytes -= 1 if line.getbyte(hash + bytes + bytes - 1) == SPACE
        end
        return true unless selected_at?(line, close + 2, id_start - 1)

        time = (line.byteslice(1, close - 8).to_i * 1_000_000) + line.byteslice(close - 6, 6).to_i
        in_order(time)
        if extended && id & Frame::ERR_FLAG != 0 then traffic.count_error(time)
        else traffic.count(extended ? id | Frame::EFF_FLAG : id, time, fd, mark == RTR_MARK, bytes)
        end
        true
      end

      # #selected? for the interface name between +start+ (maybe padding
      # spaces) and +stop+, compared in place: no string is made for the
      # name of the interface being read.
      def selected_at?(line, start, stop)
        start += 1 while line.getbyte(start) == SPACE
        iface = @interface
        return true if iface && stop - start == iface.bytesize && line.index(iface, start) == start

        selected?(line.byteslice(start, stop - start))
      end

      def count_parsed(line, traffic)
        frame, iface = parse(line)
        return unless frame && selected?(iface)

        in_order(frame.time)
        traffic.add(frame)
      end

      # Notes a frame time earlier than the one before it: gaps and periods
      # are measured in log order, which is then not time order.
      def in_order(time)
        previous = @previous_time
        @previous_time = time
        return if previous.nil? || time >= previous

        @backwards ||= Backwards.new(@lines, time, previous, 0)
        @backwards.lines += 1
      end

      # Data bytes of a CAN FD line: from after ##F to the end of the frame.
      def fd_length(line, hash)
        stop = line.index(' ', hash) || (line.bytesize - (line.end_with?("\n") ? 1 : 0))
        (stop - hash - 3) / 2
      end

      def parse(line)
        CandumpLine.parse(line)
      rescue CandumpLine::Malformed => e
        # Only the last line of a file can lack its end of line: a log cut
        # short while candump was writing it.
        message = line.end_with?("\n") ? e.message : "last line cut short (no end of line): #{e.message}"
        record_malformed(message, line.chomp)
      end

      def record_malformed(message, text)
        @malformed_count += 1
        @malformed << Malformed.new(@lines, message, text) if @malformed.size < KEEP_MALFORMED
        nil
      end

      # Whether frames of +iface+ are read; the first interface seen is read
      # unless one was chosen.
      def selected?(iface)
        @interface ||= iface
        return true if iface == @interface

        @other_interfaces[iface] += 1
        false
      end
    end
  end
end
