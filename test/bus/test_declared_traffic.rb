# frozen_string_literal: true

require 'helper'
require 'stringio'
require 'syskit/bus/candump_log'
require 'syskit/bus/declared_traffic'

module Syskit
  module Bus
    # A log against the frames a plan declares on its bus.
    class TestDeclaredTraffic < Minitest::Test
      def declared_frame(id, period, jitter: 0, extended: false)
        Network::Plan::Frame.new(id, extended, 8, period, period, jitter, "d#{id}", 'base.rb:1')
      end

      def traffic(text)
        traffic = Traffic.new
        CandumpLog.new('test.log').read(StringIO.new(text), traffic)
        traffic
      end

      # 0x100 every 10 ms, once 12 ms late; 0x200 once; 0x300 unknown.
      LOG = <<~LOG
        (1.000000) can0 100#0001020304050607
        (1.010000) can0 100#0001020304050607
        (1.022000) can0 100#0001020304050607
        (1.030000) can0 100#0001020304050607
        (1.035000) can0 300#01
        (1.040000) can0 200#0001020304050607
      LOG

      def compare(*frames, bitrate: 500_000)
        bus = Network::Plan::Bus.new('can0', bitrate, Rational(1, 10), frames)
        DeclaredTraffic.new(bus, traffic(LOG))
      end

      def test_per_declared_frame
        declared = compare(declared_frame(0x100, Rational(1, 100)), declared_frame(0x200, 1),
                           declared_frame(0x123, 1, extended: true))
        seen, once, never = declared.rows
        assert_equal [4, Rational(1, 100), Rational(12, 1000)], [seen.frames, seen.mean_period, seen.worst_period]
        assert seen.late?, '12 ms is more than the 10 ms period'
        assert_equal [1, nil, nil], [once.frames, once.mean_period, once.worst_period]
        refute once.late?
        assert_equal [never], declared.unseen
        assert_equal [[0x300, 1]], declared.undeclared.map(&:to_a)
      end

      def test_jitter_allows_later_frames
        declared = compare(declared_frame(0x100, Rational(1, 100), jitter: Rational(2, 1000)))
        refute declared.rows.first.late?
      end

      # The log's end hides a device that fell silent from the gaps
      # between its frames: the time since its last frame says it.
      def test_a_frame_that_stops_before_the_log_ends_is_silent_at_the_end
        refute compare(declared_frame(0x100, Rational(1, 100))).rows.first.silent_at_end?, 'one period before the end'
        bus = Network::Plan::Bus.new('can0', 500_000, nil, [declared_frame(0x100, Rational(1, 100))])
        log = "#{LOG}(1.230000) can0 300#01\n"
        row = DeclaredTraffic.new(bus, traffic(log)).rows.first
        assert row.silent_at_end?
        assert_equal Rational(200, 1000), row.silent_for
        assert_in_delta 0.2, DeclaredTraffic.new(bus, traffic(log)).to_h['frames'].first['silent_at_end']
      end

      def test_the_load_over_the_log_at_the_declared_bitrate
        declared = compare(declared_frame(0x100, Rational(1, 100)))
        # 5 frames of 8 bytes (135 bits) and one of 1 byte (65 bits) in 40 ms.
        assert_equal Rational((5 * 135) + 65, 500_000) / Rational(40, 1000), declared.observed_load
        assert_equal Rational(1, 10), declared.declared_load
        assert_nil compare(bitrate: nil).observed_load
      end

      def test_as_plain_data
        plain = compare(declared_frame(0x100, Rational(1, 100)), declared_frame(0x123, 1, extended: true)).to_h
        assert_equal %w[bus bitrate declared_load observed_load frames unseen undeclared], plain.keys
        assert_equal({ 'id' => '100', 'device' => 'd256', 'period' => 0.01, 'frames' => 4, 'mean_period' => 0.01,
                       'worst_period' => 0.012, 'late' => true, 'silent_at_end' => nil }, plain['frames'].first)
        assert_equal ['00000123'], plain['unseen']
        assert_equal [{ 'id' => '200', 'frames' => 1 }, { 'id' => '300', 'frames' => 1 }], plain['undeclared']
      end
    end
  end
end
