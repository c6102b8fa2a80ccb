# frozen_string_literal: true

require 'syskit/bus/frame'
require 'syskit/bus/candump_line'
require 'syskit/bus/candump_fields'
require 'syskit/bus/candump_runs'

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
      include CandumpFields
      include CandumpRuns

      # A line that is not a candump frame.
      Malformed = Struct.new(:lineno, :message, :text)
      # The first line whose time is before the line read before it (a log
      # merged from several, a clock set back), and how many such lines.
      Backwards = Struct.new(:lineno, :time, :previous_time, :lines)
      # How many malformed lines are kept for the report.
      KEEP_MALFORMED = 5
      # The longest line candump writes is under 300 bytes (a CAN FD frame
      # of 64 bytes). Lines are read in pieces of at most this many bytes, a
      # longer line is skipped piece by piece: memory stays bounded whatever
      # the file holds (a binary file, /dev/zero).
      MAX_LINE = 4096
      HASH_MARK = 35 # '#'
      # The end of line searched for, in the log's encoding: String#index
      # checks a needle of another encoding on every call (ASCII-8BIT data,
      # UTF-8 literal), a third of the search's cost.
      NEWLINE = "\n".b
      # The log is read this many bytes at a time (see #read).
      CHUNK = 1 << 16
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
      # +traffic+ (a Traffic); yields the number of frames counted so far
      # after every +every+ lines (or pieces of an overlong line), for
      # progress, with +traffic+ up to date.
      #
      # One loop on purpose: it runs for every line of logs of millions,
      # and every call and object made per line shows in the replay's speed
      # (doc/performance.md). The log is read CHUNK bytes at a time. Lines
      # as candump -l writes them for the interface read are checked a run
      # at a time by one regexp (#fast_runs: every line up to the first
      # that is not one or is of another second, whose seconds are then
      # converted once; #fast_mixed_runs on a quiet bus) and read by
      # position in the chunk, without a string of their own; the others
      # are cut as IO#each_line(MAX_LINE) cuts them and go through
      # #line_fields. The figures are kept in locals and handed to
      # +traffic+ every +every+ lines and at the end; the per-key tallies
      # are updated in place.
      # rubocop:disable-next Metrics -- one loop, see above
      def read(io, traffic, every: 1)
        tallies = traffic.tallies
        # Read by position once a first frame has set the times it needs.
        fast = @previous_time && traffic.last_time && fast_line
        id_start = fast && (@interface.bytesize + 21)
        runs = fast && fast_runs
        mixed_runs = fast && fast_mixed_runs
        mixed = false # whether the next run is read with mixed_runs
        frames = extended = fd_frames = fd_extended = rtr_frames = errors = bytes_total = 0
        first_time = traffic.first_time
        last_time = traffic.last_time
        previous = @previous_time
        lines = @lines
        pieces = 0
        commit = lambda do
          traffic.add_totals(frames: frames, extended: extended, fd_frames: fd_frames, fd_extended: fd_extended,
                             rtr: rtr_frames, errors: errors, bytes: bytes_total,
                             first_time: first_time, last_time: last_time)
          frames = extended = fd_frames = fd_extended = rtr_frames = errors = bytes_total = 0
          @previous_time = previous
          @lines = lines
        end
        long = false # in an overlong line, read in pieces (see #each_line)
        rest = nil # the start of a line the last chunk cut
        while (chunk = io.read(CHUNK))
          data = rest ? rest << chunk : chunk
          size = data.bytesize
          at_end = io.eof?
          pos = 0
          cut = nil
          while pos < size
            if !long && fast && (run = (mixed ? mixed_runs : runs).match(data, pos))
              # Lines as candump -l writes them, up to the first that is
              # not or that is of another second: (SSSSSSSSSS.UUUUUU) IFACE
              # III#DD.. or IIIIIIII#DD.., #R or #Rn for a remote request,
              # ##FDD.. for CAN FD.
              stop = run.end(0)
              # The same for the whole run; nil for a run of mixed seconds.
              seconds = (text = run[1]) && (text.to_i * 1_000_000)
              run_start = lines
              while pos < stop
                eol = data.index(NEWLINE, pos)
                lines += 1
                frames += 1
                id_at = pos + id_start
                if data.getbyte(id_at + 3) == HASH_MARK
                  key = data.byteslice(id_at, 3).to_i(16)
                  mark = id_at + 4 # the first byte after '#'
                else
                  key = data.byteslice(id_at, 8).to_i(16) | Frame::EFF_FLAG
                  extended += 1
                  mark = id_at + 9
                end
                case data.getbyte(mark)
                when HASH_MARK # CAN FD: its bytes are not in the classic total
                  fd_frames += 1
                  fd_extended += 1 if key >= Frame::EFF_FLAG
                when RTR_MARK then rtr_frames += 1 # a request carries no data
                else bytes_total += (eol - mark) >> 1
                end
                time = (seconds || (data.byteslice(pos + 1, 10).to_i * 1_000_000)) + data.byteslice(pos + 12, 6).to_i
                # Traffic#count and #stretch, inline (times are never nil here).
                tally = tallies[key]
                if tally.nil? then tallies[key] = [1, time, time, 0]
                else
                  tally[0] += 1
                  last = tally[2]
                  if time >= last
                    tally[3] = time - last if time - last > tally[3]
                    tally[2] = time
                  elsif time < tally[1] then tally[1] = time
                  end
                end
                if time >= last_time then last_time = time
                elsif time < first_time then first_time = time
                end
                if time < previous
                  @lines = lines
                  out_of_order(time, previous)
                end
                previous = time
                pos = eol + 1
                next unless (pieces += 1) == every

                pieces = 0
                commit.call
                yield traffic.frames if block_given?
              end
              # On a quiet bus the second changes every few lines: a match
              # per second would cost more than it saves, so a short run of
              # one second is followed by a run of any seconds (up to the
              # chunk's end or the first other line), converted per line.
              mixed = seconds && lines - run_start < SHORT_RUN
              next
            end

            # Any other line, as IO#each_line(MAX_LINE) would give it: up to
            # its end of line, or MAX_LINE bytes of an overlong one.
            eol = data.index("\n", pos)
            length = eol && eol - pos < MAX_LINE ? eol - pos + 1 : MAX_LINE
            if pos + length > size && !at_end
              cut = pos
              break
            end
            line = data.byteslice(pos, length)
            pos += line.bytesize
            fields = nil
            whole = line.bytesize < MAX_LINE || line.end_with?("\n")
            unless long
              @lines = lines += 1
              whole ? (fields = line_fields(line)) : too_long(line)
            end
            long = !whole
            if fields
              key, time, fd, rtr, bytes = fields
              frames += 1
              if key == ERROR
                errors += 1 # counted in the totals, never dispatched
              else
                extended += 1 if key >= Frame::EFF_FLAG
                rtr_frames += 1 if rtr
                if fd
                  fd_frames += 1
                  fd_extended += 1 if key >= Frame::EFF_FLAG
                else
                  bytes_total += bytes
                end
                tally = tallies[key]
                tally ? traffic.stretch(tally, time) : tallies[key] = [1, time, time, 0]
                tally[0] += 1 if tally
              end
              if last_time.nil? then first_time = last_time = time
              elsif time >= last_time then last_time = time
              elsif time < first_time then first_time = time
              end
              if previous && time < previous
                @lines = lines
                out_of_order(time, previous)
              end
              previous = time
              # From the first frame on, lines as candump writes them are
              # read by position.
              fast = fast_line
              id_start = fast && (@interface.bytesize + 21)
              runs = fast && fast_runs
              mixed_runs = fast && fast_mixed_runs
            end
            next unless (pieces += 1) == every

            pieces = 0
            commit.call
            yield traffic.frames if block_given?
          end
          rest = cut && data.byteslice(cut, size - cut)
        end
        commit.call
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

      # Notes a frame at +time+, earlier than the one before it (at
      # +previous+): gaps and periods are measured in log order, which is
      # then not time order.
      def out_of_order(time, previous)
        @backwards ||= Backwards.new(@lines, time, previous, 0)
        @backwards.lines += 1
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
