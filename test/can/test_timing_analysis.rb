# frozen_string_literal: true

require 'helper'
require 'syskit/can/timing'

module Syskit
  module CAN
    # The response-time analysis on cases computed by hand.
    class TestTimingAnalysis < Minitest::Test
      US = Rational(1, 1_000_000)
      MS = Rational(1, 1000)

      def frame(id, bytes: 8, period: 10 * MS, **options)
        Timing::Frame.build(id: id, bytes: bytes, period: period, device: "d#{id.to_s(16)}", **options)
      end

      def analyse(bitrate, *frames)
        Timing::Analysis.run(bitrate: bitrate, frames: frames)
      end

      def by_id(result)
        result.frames.to_h { |r| [r.frame.id, r] }
      end

      def test_frame_lengths_include_worst_case_stuffing_and_the_inter_frame_space
        assert_equal([55, 65, 135], [0, 1, 8].map { |s| frame(0x100, bytes: s).bits })
        assert_equal([80, 90, 160], [0, 1, 8].map { |s| frame(0x100, bytes: s, extended: true).bits })
      end

      # Davis et al.'s g + 8s + 13 + floor((g + 8s - 1) / 4), g = 34 or 54.
      def test_frame_lengths_are_the_papers
        (0..8).each do |s|
          [[34, false], [54, true]].each do |g, extended|
            assert_equal g + (8 * s) + 13 + ((g + (8 * s) - 1) / 4), frame(1, bytes: s, extended: extended).bits
          end
        end
      end

      def test_a_single_frame_takes_its_transmission_time
        only = analyse(500_000, frame(0x181)).frames.first
        assert_equal 270 * US, only.transmission_time # 135 bits of 2 us
        assert_equal 0, only.blocking
        assert_equal 270 * US, only.response_time
        assert_equal 1, only.instances
        assert_equal (10 * MS) - (270 * US), only.slack
        assert only.schedulable?
      end

      def test_a_longer_lower_priority_frame_blocks
        # 1 Mbit/s: 55 us for 0 bytes, 135 us for 8.
        high, low = analyse(1_000_000, frame(0x200, bytes: 8), frame(0x100, bytes: 0)).frames
        assert_equal [0x100, 0x200], [high.frame.id, low.frame.id]
        assert_equal 135 * US, high.blocking
        assert_equal 190 * US, high.response_time # waits for the 8-byte frame, then 55 us
        assert_equal 0, low.blocking
        assert_equal 190 * US, low.response_time  # the 0-byte frame goes first
      end

      # Davis et al. 2007, section 3: three frames of 1 ms (8 bytes at
      # 135 kbit/s), periods 2.5, 3.5 and 3.5 ms. The 1994 analysis gives the
      # lowest 3.0 ms; its second instance in the busy period takes 3.5 ms.
      def test_a_later_instance_of_the_busy_period_has_the_worst_response
        a, b, c = analyse(135_000, frame(1, period: 2.5r * MS), frame(2, period: 3.5r * MS),
                          frame(3, period: 3.5r * MS, deadline: 3.25r * MS)).frames
        assert_equal [MS] * 3, [a, b, c].map(&:transmission_time)
        assert_equal [2 * MS, 3 * MS, 3 * MS], [a.response_time, b.response_time, c.original_response_time]
        assert_equal [3.5r * MS, 1, 2], [c.response_time, c.worst_instance, c.instances]
        refute c.schedulable?, '3.5 ms misses the 3.25 ms deadline that 3.0 ms met'
        assert_equal(-0.25r * MS, c.slack)
      end

      def test_arbitration_orders_standard_and_extended_ids_as_can_2_0b
        frames = [frame(0x101, bytes: 0), frame(0x100 << 18, bytes: 0), frame(0x100, bytes: 0),
                  frame(0x7FF, bytes: 0), frame(0x1, bytes: 0, extended: true)]
        order = analyse(1_000_000, *frames).frames.map { |r| r.frame.hex_id }
        # Base ids first; a standard frame beats an extended one of the same base id.
        assert_equal %w[00000001 100 04000000 101 7FF], order
      end

      def test_mixed_standard_and_extended_response_times
        std, ext, low = analyse(1_000_000, frame(0x101, bytes: 0, period: MS), frame(0x4000000, bytes: 0, period: MS),
                                frame(0x100, bytes: 0, period: MS)).frames.sort_by { |r| r.frame.arbitration_key }
        assert_equal([0x100, 0x4000000, 0x101], [std, ext, low].map { |r| r.frame.id })
        assert_equal 80 * US, ext.transmission_time
        assert_equal [80 * US, 55 * US, 0], [std.blocking, ext.blocking, low.blocking]
        assert_equal [135 * US, 190 * US, 190 * US], [std.response_time, ext.response_time, low.response_time]
      end

      def test_jitter_delays_a_frame_and_lets_higher_ones_interfere_more
        high = frame(0x100, bytes: 0, period: 200 * US, jitter: 150 * US)
        low = frame(0x200, bytes: 8, period: MS, jitter: 100 * US)
        results = by_id(analyse(1_000_000, high, low))
        # Two instances of 0x100 (55 us) can be queued within 0x200's wait;
        # 0x200's own jitter counts in its response time.
        assert_equal 345 * US, results[0x200].response_time
        # 0x100: its jitter, blocked by 0x200 (135 us), then 55 us.
        assert_equal 340 * US, results[0x100].response_time
        # Two instances are queued in its busy period, but with nothing
        # above it the first responds latest: only it is examined.
        assert_equal 1, results[0x100].instances
        # Without jitter: one instance of 0x100, then 0x200.
        without = by_id(analyse(1_000_000, frame(0x100, bytes: 0, period: 200 * US), frame(0x200, period: MS)))
        assert_equal 190 * US, without[0x200].response_time
      end

      # The paper's example with the deadline at the period: the second
      # instance is still the worst, and it meets its deadline.
      def test_a_later_instance_that_meets_its_deadline
        c = analyse(135_000, frame(1, period: 2.5r * MS), frame(2, period: 3.5r * MS), frame(3, period: 3.5r * MS))
            .frames.last
        assert_equal [3.5r * MS, 1, 2, false], [c.response_time, c.worst_instance, c.instances, c.stopped_at_miss]
        assert c.schedulable?
      end

      # 100,000 s of jitter on a 1 ms frame queues 10^8 instances in its
      # busy period: a jitter only adds instances that respond no later, so
      # the work (instances examined) does not grow with it.
      def test_a_large_jitter_costs_no_more_instances
        results = [0, 100_000].map do |jitter|
          analyse(500_000, frame(0x100, period: 2 * MS), frame(0x200, period: MS, jitter: jitter)).frames.last
        end
        assert_equal [1, 1], results.map(&:instances)
        assert_equal 100_000 + (540 * US), results.last.response_time # its jitter, 0x100, then itself
        refute results.last.schedulable?
        refute results.last.stopped_at_miss, 'no instance after the first can respond later'
      end

      def test_a_large_jitter_with_a_later_deadline_is_analysed_exactly
        a, b, c = analyse(135_000, frame(1, period: 2.5r * MS), frame(2, period: 3.5r * MS),
                          frame(3, period: 3.5r * MS, jitter: 100_000, deadline: 200_000)).frames
        assert_equal [2 * MS, 3 * MS], [a.response_time, b.response_time]
        # As without jitter, the second instance is the worst: 100,000 s
        # later. 5 instances of 3.5 ms make the 17.5 ms the periods repeat in.
        assert_equal [100_000 + (3.5r * MS), 1, 5], [c.response_time, c.worst_instance, c.instances]
        assert c.schedulable?
      end

      def test_a_higher_frame_with_a_large_jitter_makes_the_lower_ones_miss
        results = analyse(135_000, frame(1, period: 2.5r * MS, jitter: 100_000), frame(2, period: 3.5r * MS),
                          frame(3, period: 3.5r * MS)).frames
        assert_equal [1, 1, 1], results.map(&:instances)
        assert(results.none?(&:schedulable?))
      end

      # The first instance that misses ends the analysis of the frame: it
      # misses, and its response is a lower bound of the worst.
      def test_the_first_late_instance_ends_the_analysis_of_a_frame
        c = analyse(135_000, frame(1, period: 2.5r * MS), frame(2, period: 3.5r * MS),
                    frame(3, period: 3.5r * MS, jitter: 0.75r * MS)).frames.last
        assert_equal [3.75r * MS, 0, 1, true], [c.response_time, c.worst_instance, c.instances, c.stopped_at_miss]
        refute c.schedulable?
        assert_equal true, c.to_h['stopped_at_miss']
      end

      def test_an_overloaded_bus_is_reported_not_iterated
        # 1.08 ms frames: 10.8 % + 54 % + 54 %.
        results = analyse(125_000, frame(1, period: 10 * MS), frame(2, period: 2 * MS), frame(3, period: 2 * MS))
        assert_equal [true, Rational(1188, 1000)], [results.overloaded?, results.utilization]
        first, second, third = results.frames
        assert_equal [Rational(216, 100) * MS, Rational(324, 100) * MS], [first.response_time, second.response_time]
        assert_nil third.slack
        refute results.schedulable?
        assert_equal([2, 3], results.misses.map { |r| r.frame.id })
      end

      def test_a_bus_loaded_exactly_100_percent_is_overloaded
        results = analyse(135_000, frame(1, period: 2 * MS), frame(2, period: 2 * MS))
        assert_equal 1, results.utilization
        assert results.overloaded?
        assert_nil results.frames.last.response_time
      end

      def test_times_are_exact_whatever_numbers_they_are_written_with
        built = frame(0x10, period: 0.001, deadline: Rational(1, 2000), jitter: 0)
        assert_equal [MS, MS / 2, 0], [built.period, built.deadline, built.jitter]
        assert_kind_of Rational, built.period
        result = analyse(500_000, built, frame(0x20, period: 0.003))
        assert_kind_of Rational, result.frames.last.response_time
      end

      def test_an_empty_bus
        result = analyse(500_000)
        assert_equal 0, result.utilization
        assert result.schedulable?
      end

      def test_invalid_frames_say_what_to_write
        {
          { bytes: 9 } => 'bytes: takes 0 to 8',
          { bytes: -1 } => 'bytes: takes 0 to 8',
          { period: 0 } => 'period: takes seconds',
          { period: -0.01 } => 'period: takes seconds',
          { period: '10ms' } => 'period: takes seconds',
          { deadline: 0 } => 'deadline: takes seconds',
          { jitter: -1 } => 'jitter: takes seconds',
          { id: 0x2000_0000 } => '29 bits',
          { id: -1 } => '29 bits',
          { id: 0x800, extended: false } => 'drop extended: false'
        }.each do |options, hint|
          error = assert_raises(Timing::InvalidFrame, options.inspect) do
            Timing::Frame.build(id: 0x100, bytes: 8, period: 0.01, **options)
          end
          assert_includes error.hint, hint, options.inspect
        end
        assert_raises(ArgumentError) { Timing::Analysis.run(bitrate: 0, frames: []) }
      end
    end
  end
end
