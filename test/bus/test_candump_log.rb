# frozen_string_literal: true

require 'helper'
require 'syskit/bus/candump_log'
require 'syskit/bus/traffic'

module Syskit
  module Bus
    # Reading candump logs: the full line parser, and the fast reader that
    # must count exactly what the full parser reads.
    class TestCandumpLog < Minitest::Test
      def parse(text)
        CandumpLine.parse(text)
      end

      def frame(text)
        parse("(1436509053.249713) can0 #{text}\n").first
      end

      def test_a_standard_frame
        f, iface = parse("(1436509053.249713) can0 123#DEADBEEF\n")
        assert_equal 'can0', iface
        assert_equal [0x123, false, 4, "\xDE\xAD\xBE\xEF".b], [f.id, f.extended?, f.len, f.data]
        assert_equal 1_436_509_053_249_713, f.time
        refute f.fd?
        refute f.rtr?
      end

      def test_an_extended_frame_has_8_digits
        f = frame('00000123#00')
        assert f.extended?
        assert_equal 0x123, f.id
        assert_equal 0x123 | Frame::EFF_FLAG, f.key
        refute_equal frame('123#00').key, f.key
      end

      def test_rtr_frames_with_and_without_length
        assert_equal [true, 0, ''.b], [frame('123#R').rtr?, frame('123#R').len, frame('123#R').data]
        assert_equal 3, frame('123#R3').len
        assert frame('12345678#r').rtr?
      end

      def test_can_fd_frames_take_their_flags_from_the_digit_after_the_double_hash
        f = frame('123##1DEADBEEF')
        assert f.fd?
        assert_equal 1, f.fd_flags
        assert_equal 4, f.len
        assert_equal 12, frame("123##0#{'00' * 12}").len
      end

      def test_error_frames
        f = frame('20000004#0000080000000000')
        assert f.error?
        refute f.extended?
        assert_equal 4, f.id
      end

      def test_accepted_spellings
        assert_equal 3, frame('123#11.22.33').len, 'dots between bytes'
        assert_equal 8, frame('123#1122334455667788_9').len, 'len8_dlc suffix'
        assert_equal "\xAB".b, frame('1ab#ab').data, 'lower case'
        assert_equal 'vcan0', parse("(1.000000)  vcan0 123#00\n").last, 'interface names padded to align'
        assert_equal 0x123, parse("(1.000000) can0 123#00 T\n").first.id, 'candump -x direction'
        assert_equal 0x123, parse("(1.000000) can0 123#00\r\n").first.id, 'CRLF'
        assert_equal 1_500_000, parse("(1.5) can0 123#00\n").first.time, 'short fraction'
      end

      def test_malformed_lines_say_what_is_wrong
        {
          'garbage' => /expected '\(seconds.microseconds\) interface frame'/,
          '(1.000000) can0 123' => /no '#' after the id/,
          '(1.000000) can0 1234#00' => /bad id '1234': 3 hex digits for a standard frame, 8 for an extended one/,
          '(1.000000) can0 800#00' => /standard id 800 does not fit in 11 bits/,
          '(1.000000) can0 40000000#00' => /bits set beyond the 29-bit id/,
          '(1.000000) can0 123#123' => /pairs of hex digits/,
          '(1.000000) can0 123#GG' => /pairs of hex digits/,
          '(1.000000) can0 123#112233445566778899' => /9 data bytes .* at most 8/,
          '(1.000000) can0 123##1112233445566778899' => /CAN FD frame cannot have 9 data bytes/,
          '(1.000000) can0 123##G00' => /CAN FD flags/,
          '(1.000000) can0 123###00' => /CAN XL frames \(###\) are not supported/,
          '(1.000000) can0 123#R9' => /bad RTR length '9'/
        }.each do |line, message|
          error = assert_raises(CandumpLine::Malformed, line) { parse("#{line}\n") }
          assert_match message, error.message, line
        end
      end

      def test_blank_lines_are_skipped
        assert_nil parse("\n")
        assert_nil parse("   \n")
      end

      def test_frames_write_themselves_back_as_candump_does
        %w[123#DEADBEEF 123# 00000123#00 1FFFFFFF#0102 123#R 123#R3 123##1DEADBEEF 20000004#0000080000000000]
          .each { |text| assert_equal text, frame(text).to_candump }
      end

      MIXED = <<~LOG.freeze
        (1436509053.249713) can0 123#DEADBEEF
        (1436509053.249800)  can0 00000123#00 R
        (1436509053.249900) can1 123#00
        (1436509053.249950) can1 800#00
        (1436509053.250000) can0 123#R
        (1436509053.250100) can0 123#R4
        (1436509053.250200) can0 7FF##1#{'00' * 64}
        (1436509053.250300) can0 7FF##1#{'00' * 13}
        (1436509053.250400) can0 20000004#0000080000000000
        (1436509053.250500) can0 1ab#ab.cd
        (1436509053.250600) can0 123#11_9
        (1436509053.2507) can0 800#00
        (1436509053.250800) can0 1FFFFFFF#
        (1436509053.250900) can0 3FFFFFFF#00
        (1436509053.251000) can0 123#00\r
        (1436509053.251100) can0 12#00
        (1436509053.249000) can0 123#00
        (1436509053.251200) can0 123#00
      LOG

      def read_fast(text)
        traffic = Traffic.new
        log = CandumpLog.new('test.log').read(StringIO.new(text), traffic)
        [log, traffic]
      end

      def read_frames(text)
        traffic = Traffic.new
        log = CandumpLog.new('test.log').each_frame(StringIO.new(text)) { |f| traffic.add(f) }
        [log, traffic]
      end

      def summary(log, traffic)
        ids = traffic.ids.transform_values(&:to_a)
        [ids, traffic.frames, traffic.extended, traffic.fd, traffic.rtr, traffic.errors,
         traffic.first_time, traffic.last_time, log.malformed_count, log.malformed.map(&:lineno),
         log.other_interfaces, log.lines, traffic.bits]
      end

      def test_the_fast_reader_counts_what_the_full_parser_reads
        fast = summary(*read_fast(MIXED))
        assert_equal summary(*read_frames(MIXED)), fast
        ids, frames, extended, fd, rtr, errors, first, last, malformed, = fast
        assert_equal [13, 2, 1, 2, 2, 4], [frames, extended, fd, rtr, errors, malformed]
        assert_equal [1_436_509_053_249_000, 1_436_509_053_251_200], [first, last]
        # Out-of-order times still give the earliest and latest; the
        # longest gap is between frames in log order.
        assert_equal [7, 1_436_509_053_249_000, 1_436_509_053_251_200, 500], ids[0x123]
      end

      # Lines of every spelling, in and out of time order, of several
      # interfaces, some malformed, some cut short: the reader's fast path
      # (lines as candump -l writes them) and its other paths together
      # count what the full parser reads.
      def test_the_fast_reader_on_a_log_of_every_kind_of_line
        random = Random.new(28)
        time = 1_436_509_053_000_000
        lines = Array.new(4000) do
          time += random.rand(-40..300)
          random_line(random, time)
        end
        text = "#{lines.join("\n")}\n"
        fast = summary(*read_fast(text))
        assert_equal summary(*read_frames(text)), fast
        assert_operator fast[1], :>, 1500, 'many lines are frames of can0'
        assert_operator fast[8], :>, 100, 'some lines are malformed'
      end

      # The reader takes the log CandumpLog::CHUNK bytes at a time: a line
      # the end of a chunk cuts (a frame read by position, a remote
      # request, another interface, a malformed or overlong line) counts
      # as read whole, wherever the cut falls in it.
      def test_lines_cut_by_the_end_of_a_chunk_are_read_whole
        specials = ['(1436509053.500000) can0 18FF0001#0102', '(1436509053.500001) can0 123#R',
                    '(1436509053.500002) can1 123#00', '(1436509053.5000', 'x' * 5000,
                    '(1436509053.500003) can0 7FF##1DEADBEEF']
        fast_line = "(1436509053.000000) can0 123#0102\n"
        filler = fast_line * ((CandumpLog::CHUNK - 6000) / fast_line.size)
        specials.each do |special|
          [1, 2, 10, special.size / 2, special.size - 1, special.size, special.size + 1].each do |inside|
            # The special line starts +inside+ bytes before the chunk ends,
            # after a malformed line that pads the filler up to there.
            pad = CandumpLog::CHUNK - inside - filler.size - 1
            text = "#{filler}#{'x' * pad}\n#{special}\n(1436509053.900000) can0 123#01\n"
            assert_equal summary(*read_frames(text)), summary(*read_fast(text)), "#{special[0, 40]}, #{inside}"
          end
        end
      end

      def random_line(random, time)
        id, data = random_frame(random)
        seconds = random.rand(20).zero? ? (time / 1_000_000 % 1000).to_s : format('%010d', time / 1_000_000)
        interface = %w[can0 can0 can0 can1 vcan0].sample(random: random)
        padding = random.rand(15).zero? ? '  ' : ' '
        line = "(#{seconds}.#{format('%06d', time % 1_000_000)})#{padding}#{interface} #{id}##{data}" \
               "#{' R' if random.rand(20).zero?}"
        random.rand(60).zero? ? line[0, random.rand(line.size)] : line
      end

      # Ids in and out of range, error frames; data of every kind, some bad.
      def random_frame(random)
        [[format('%03X', random.rand(0x900)), format('%08X', random.rand(0x4000_0000)),
          format('%03X', random.rand(0x800)), format('%08X', random.rand(0x2000_0000))].sample(random: random),
         ['R', "R#{random.rand(10)}", "#1#{'AB' * [0, 8, 12, 13].sample(random: random)}", 'ZZ', '12.34',
          'A5' * random.rand(10), 'A5' * random.rand(9), '5A' * random.rand(9)].sample(random: random)]
      end

      def test_progress_comes_with_the_traffic_up_to_date
        text = Array.new(10) { |i| format("(1436509053.%06d) can0 123#00\n", i) }.join
        traffic = Traffic.new
        seen = []
        CandumpLog.new('test.log').read(StringIO.new(text), traffic, every: 4) do |frames|
          seen << [frames, traffic.frames]
        end
        assert_equal [[4, 4], [8, 8]], seen
        assert_equal 10, traffic.frames
      end

      def test_the_bits_frames_take_on_the_wire
        _, traffic = read_fast(<<~LOG)
          (1.000000) can0 123#DEADBEEF
          (1.000100) can0 00000123#00 R
          (1.000200) can0 123#R4
          (1.000300) can0 124# T
          (1.000400) can0 7FF##1#{'00' * 12}
        LOG
        # 55 + 10 per byte (standard), 80 + 10 per byte (extended); a remote
        # request carries no data; CAN FD frames are not counted.
        assert_equal 95 + 90 + 55 + 55, traffic.bits
      end

      def test_the_fast_reader_skips_other_interfaces
        log, traffic = read_fast(MIXED)
        assert_equal 'can0', log.interface
        assert_equal({ 'can1' => 1 }, log.other_interfaces)
        refute_nil traffic.ids[0x123]
      end

      def test_a_line_cut_short_at_the_end_of_the_log
        log, = read_fast("(1436509053.249713) can0 123#00\n(1436509053.2")
        assert_equal 1, log.malformed_count
        assert_match(/\Alast line cut short \(no end of line\): /, log.malformed.first.message)
        assert_equal 2, log.malformed.first.lineno
      end

      def test_a_line_too_long_for_candump_is_malformed_and_skipped
        text = "(1436509053.249713) can0 123#00\n#{'x' * 10_000}\n(1436509053.249714) can0 123#01\n"
        [read_fast(text), read_frames(text)].each do |log, traffic|
          assert_equal [2, 1, 3], [traffic.frames, log.malformed_count, log.lines]
          assert_equal 2, log.malformed.first.lineno
          assert_match(/\Alonger than 4096 bytes, which no candump line is/, log.malformed.first.message)
          assert_equal "#{('x' * 40).inspect}...", log.malformed.first.text
        end
      end

      # /dev/zero as a log: one endless line. It is read in pieces, so the
      # memory it takes does not grow with it: 96 MB of zeros through a
      # pipe, and the strings alive while it is read (garbage collected
      # first) stay within a few MB.
      def test_an_endless_line_is_read_in_bounded_memory
        require 'objspace'
        reader, writer = IO.pipe
        feeder = Thread.new do
          chunk = "\0" * (1 << 20)
          96.times { writer.write(chunk) }
          writer.close
        end
        start = live_strings
        peak = start
        pieces = 0
        log = CandumpLog.new('zero.log').read(reader, Traffic.new) do
          pieces += 1
          peak = [peak, live_strings].max if pieces == 1 || (pieces % 4096).zero?
        end
        feeder.join
        assert_operator peak - start, :<, 16 << 20, 'the line was held in memory'
        assert_equal [1, 1], [log.lines, log.malformed_count]
      ensure
        reader&.close
      end

      def live_strings
        GC.start
        ObjectSpace.memsize_of_all(String)
      end

      def test_a_chosen_interface
        traffic = Traffic.new
        log = CandumpLog.new('test.log', interface: 'can1').read(StringIO.new(MIXED), traffic)
        assert_equal 1, traffic.frames
        assert_equal 'can1', log.interface
      end
    end
  end
end
