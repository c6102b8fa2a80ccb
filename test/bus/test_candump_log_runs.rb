# frozen_string_literal: true

require 'helper'
require 'syskit/bus/candump_log'
require 'syskit/bus/traffic'

module Syskit
  module Bus
    # The runs of lines CandumpLog#read reads by position end where the
    # second changes (it converts a run's seconds once): every figure must
    # be the same as when each line's time is read whole.
    class TestCandumpLogRuns < Minitest::Test
      # Seconds kept for a few lines each, then changed: by one, forwards
      # and back, and by a power of ten (the same last digits, another
      # first one), so that a run that wrongly kept its first line's
      # seconds would count other times.
      SECONDS = [1_436_509_053, 1_436_509_054, 1_436_509_052, 1_436_509_063, 1_536_509_053, 436_509_053].freeze

      # +change+: one line in +change+ (on average) is of other seconds.
      def log_text(random, lines, change)
        seconds = SECONDS.first
        Array.new(lines) do
          seconds = SECONDS.sample(random: random) if random.rand(change).zero?
          id = [format('%03X', random.rand(0x800)), format('%08X', random.rand(0x2000_0000))].sample(random: random)
          data = ['R', "#1#{'AB' * 8}", '5A' * random.rand(9)].sample(random: random)
          time = format('%<s>010d.%<us>06d', s: seconds, us: random.rand(1_000_000))
          "(#{time}) can0 #{id}##{data}\n"
        end.join
      end

      # What the reader found, backwards times included.
      def summary(text)
        traffic = Traffic.new
        log = CandumpLog.new('test.log').read(StringIO.new(text), traffic)
        [traffic.ids.transform_values(&:to_a), traffic.frames, traffic.extended, traffic.fd, traffic.rtr,
         traffic.first_time, traffic.last_time, traffic.bits, log.lines, log.malformed_count, log.backwards.to_a]
      end

      # A busy bus: runs of one second, some shorter than
      # CandumpLog::SHORT_RUN, across chunk ends.
      def test_times_are_read_whole_where_the_second_changes
        assert_same_as_line_by_line(log_text(Random.new(40), 6000, 12))
      end

      # A quiet bus: the second changes every line or two, so that runs of
      # mixed seconds follow the short runs of one.
      def test_times_are_read_whole_when_the_second_changes_every_few_lines
        assert_same_as_line_by_line(log_text(Random.new(41), 6000, 2))
      end

      def assert_same_as_line_by_line(text)
        assert_operator text.bytesize, :>, 3 * CandumpLog::CHUNK, 'several chunks'
        # Two spaces before the interface, as candump pads short names:
        # the same lines, read one by one by CandumpFields (whole times).
        padded = text.gsub(') can0 ', ')  can0 ')
        fast = summary(text)
        assert_equal summary(padded), fast
        assert_equal [6000, 0], fast.values_at(1, 9)
        assert_equal [436_509_053, 1_536_509_053], [fast[5] / 1_000_000, fast[6] / 1_000_000]
        assert_operator fast[10][3], :>, 500, 'many lines go back in time'
      end
    end
  end
end
