# frozen_string_literal: true

require 'helper'
require 'syskit/bus/replay'
require 'syskit/bus/dispatcher'

module Syskit
  module Bus
    # The progress bar of long replays.
    class TestProgress < Minitest::Test
      # A terminal, as far as the bar can tell.
      class Terminal < StringIO
        def tty?
          true
        end
      end

      def test_no_bar_off_a_terminal_or_for_a_small_log
        assert_nil Progress.for(100 << 20, out: StringIO.new)
        assert_nil Progress.for(1 << 20, out: Terminal.new)
        assert_nil Progress.for(100 << 20, out: nil)
        refute_nil Progress.for(100 << 20, out: Terminal.new)
      end

      def test_draws_then_erases_the_bar
        out = Terminal.new
        bar = Progress.for(1000, out: out, min_bytes: 0)
        bar.update(500, 12_345)
        assert_equal "\r[#{'#' * 15}#{' ' * 15}]  50% 12345 frames", out.string
        bar.update(600, 12_346)
        assert_equal 1, out.string.count("\r"), 'redrawn at most every 0.1 s'
        bar.finish
        assert out.string.end_with?("\r\e[K")
      end

      def test_a_long_replay_shows_the_bar_on_a_terminal
        path = File.join(Dir.mktmpdir('syskit-test').tap { |d| (@tmpdirs ||= []) << d }, 'big.log')
        File.write(path, Array.new(Replay::PROGRESS_EVERY + 10) { |i| format("(1.%06d) can0 123#00\n", i) }.join)
        dev = Network::Plan::Device.with(name: 'a', bus: 'can0', bus_to_client: true,
                                         attributes: { 'can_id' => [0x123, 0x7FF] })
        out = Terminal.new
        report = Replay.new(Dispatcher.new('can0', [dev]), path, progress_out: out, progress_min_bytes: 0).run
        assert_equal Replay::PROGRESS_EVERY + 10, report.devices.first.frames
        assert_match(/\A\r\[#+ *\] +\d+% \d+ frames\r\e\[K\z/, out.string)
      end
    end
  end
end
