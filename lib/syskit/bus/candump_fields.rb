# frozen_string_literal: true

require 'syskit/bus/frame'
require 'syskit/bus/candump_line'

module Syskit
  module Bus
    # How CandumpLog reads the lines its loop does not read by position
    # (CandumpLog#read): lines of candump's other spellings (padded
    # interface names, remote requests, CAN FD, candump -x flags, times of
    # other widths) by index arithmetic, the rest (malformed lines
    # included) by CandumpLine, whose messages say what is wrong. Uses the
    # log's interface (@interface, chosen by the first frame) and records
    # what it skips.
    module CandumpFields
      # A line as candump writes it, checked whole without captures (no
      # allocation): lines that pass are read by index arithmetic, the
      # others (rare: malformed or unusual spellings) by CandumpLine.
      WRITTEN = /\A\(\d+\.\d{6}\) +[^ \n]+ (?:\h{3}|\h{8})#(?:R[0-8]?|#\h(?:\h\h){0,64}|(?:\h\h){0,8})(?: [RT])?\n?\z/
      SPACE = 32
      FD_MARK = 35 # '#'
      RTR_MARK = 82 # 'R'
      # What #line_fields gives for an error frame, and what
      # #written_fields gives for a line CandumpLine must read.
      ERROR = :error
      PARSE = :parse

      private

      # The fields of a line (see #read) that is not as #fast_line reads
      # it: [key, time, fd, rtr, bytes], [ERROR, time] for an error frame,
      # nil for a line of another interface or a malformed one (recorded).
      def line_fields(line)
        fields = written_fields(line)
        fields == PARSE ? parsed_fields(line) : fields
      end

      # The fields of a line that matches WRITTEN, read by position; PARSE
      # when its values need CandumpLine's checks and messages.
      # rubocop:disable-next Metrics/AbcSize, Metrics/CyclomaticComplexity, Metrics/PerceivedComplexity -- one reading
      def written_fields(line)
        return PARSE unless line.match?(WRITTEN)

        close = line.index(')')
        # The id is the 3 or 8 digits before the first '#' after the time.
        hash = line.index('#', close)
        extended = line.getbyte(hash - 4) != SPACE
        id_start = extended ? hash - 8 : hash - 3
        id = line.byteslice(id_start, hash - id_start).to_i(16)
        return PARSE if id > (extended ? 0x3FFF_FFFF : Frame::SFF_MASK)

        mark = line.getbyte(hash + 1)
        fd = mark == FD_MARK
        bytes = 0 # a remote request carries none
        if fd
          bytes = fd_length(line, hash)
          return PARSE unless Frame::CANFD_LENGTHS.include?(bytes)
        elsif mark != RTR_MARK
          # Half the characters after #, whether an end of line follows or
          # not; one less when the " R"/" T" flags of candump -x do.
          bytes = (line.bytesize - hash - 1) >> 1
          bytes -= 1 if line.getbyte(hash + bytes + bytes - 1) == SPACE
        end
        return unless selected_at?(line, close + 2, id_start - 1)

        time = (line.byteslice(1, close - 8).to_i * 1_000_000) + line.byteslice(close - 6, 6).to_i
        return [ERROR, time] if extended && id & Frame::ERR_FLAG != 0

        [extended ? id | Frame::EFF_FLAG : id, time, fd, mark == RTR_MARK, bytes]
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

      def parsed_fields(line)
        frame, iface = parse(line)
        return unless frame && selected?(iface)
        return [ERROR, frame.time] if frame.error?

        [frame.key, frame.time, frame.fd?, frame.rtr?, frame.rtr? ? 0 : frame.len]
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
    end
  end
end
