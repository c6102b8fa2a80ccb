# frozen_string_literal: true

require 'helper'
require 'syskit/can/timing'

module Syskit
  module CAN
    # The analysis against a simulation of CAN arbitration, bit time by
    # bit time, from the worst-case release pattern of each frame (Davis
    # et al. 2007, section 4): the longest lower-priority frame starts just
    # before the frame and every higher-priority one is queued; each is
    # queued first after its full jitter, then as early as its period
    # allows. The analysis claims the worst response of that pattern, so
    # both must agree exactly, on random frame sets.
    class TestTimingSimulation < Minitest::Test
      # One bit per millisecond: times in the simulation are whole bits.
      BITRATE = 1000

      # A frame of the simulation: arbitration key, length, period and
      # jitter in bits.
      SimFrame = Struct.new(:key, :bits, :period, :jitter) do
        # Instance n is released at n * period - jitter and queued at
        # max(0, n * period - jitter): instance 0 after its whole jitter,
        # the next ones without jitter.
        def queued(instance)
          [(instance * period) - jitter, 0].max
        end

        def released(instance)
          (instance * period) - jitter
        end
      end

      # The worst response time, in bits, of frame +index+ of +frames+
      # (sorted by priority) over +horizon+ bits from its critical instant.
      def simulate(frames, index, horizon)
        contenders = frames.first(index + 1)
        sent = Array.new(contenders.size, 0)
        # The blocker won arbitration alone, just before the others were queued.
        time = frames.drop(index + 1).map(&:bits).max || 0
        worst = 0
        while time < horizon
          winner = arbitrate(contenders, sent, time)
          next time = next_queued(contenders, sent) unless winner

          finish = time + contenders[winner].bits
          worst = [worst, finish - contenders[winner].released(sent[winner])].max if winner == index
          sent[winner] += 1
          time = finish
        end
        worst
      end

      # Arbitration at a bit boundary: the highest frame queued by then wins.
      def arbitrate(contenders, sent, time)
        contenders.each_index.find { |i| contenders[i].queued(sent[i]) <= time }
      end

      # Idle bits until the next frame is queued are skipped at once:
      # stepping one bit at a time would find nothing before.
      def next_queued(contenders, sent)
        contenders.each_index.map { |i| contenders[i].queued(sent[i]) }.min
      end

      def random_frames(random)
        count = random.rand(2..6)
        keys = {}
        Array.new(count) do
          extended = random.rand < 0.4
          id = extended ? random.rand(0..0x1FFF_FFFF) : random.rand(0..0x7FF)
          period = random.rand(150..1500)
          jitter = random.rand < 0.5 ? 0 : random.rand(0..period)
          # Deadlines past the period let several instances meet theirs.
          deadline = random.rand < 0.7 ? period : random.rand(period..(4 * period))
          Timing::Frame.build(id: id, extended: extended, bytes: random.rand(0..8),
                              period: Rational(period, BITRATE), deadline: Rational(deadline, BITRATE),
                              jitter: Rational(jitter, BITRATE), device: "d#{keys.size}")
        end.uniq(&:arbitration_key)
      end

      def test_the_analysis_agrees_with_the_simulation_on_random_frame_sets
        random = Random.new(20_07)
        checked = []
        600.times do
          result = Timing::Analysis.run(bitrate: BITRATE, frames: random_frames(random))
          # Near 100 %, busy periods span thousands of periods: too long to simulate.
          checked.concat(compare(result)) if result.utilization <= 0.9
        end
        assert_operator checked.size, :>, 1000
        assert(checked.any? { |r| r.instances > 1 && !r.stopped_at_miss }, 'some frames need several instances')
        assert(checked.any?(&:stopped_at_miss), 'some frames miss before the instance that responds latest')
      end

      # Asserts the simulation finds the analysis's response time for each
      # frame of +result+; returns the frames' results.
      def compare(result)
        sim = result.frames.map do |r|
          f = r.frame
          SimFrame.new(f.arbitration_key, f.bits, (f.period * BITRATE).to_i, (f.jitter * BITRATE).to_i)
        end
        horizon = 30 * sim.map(&:period).max
        result.frames.each_with_index do |r, index|
          assert_agrees(r, simulate(sim, index, horizon), "frame #{index} of #{result.frames.map(&:frame).inspect}")
        end
      end

      def assert_agrees(result, simulated, message)
        return assert_equal(result.response_time * BITRATE, simulated, message) unless result.stopped_at_miss

        # Stopped at its first late instance: a later one may take longer.
        assert_operator result.response_time * BITRATE, :<=, simulated, message
        assert_operator result.frame.deadline * BITRATE, :<, simulated, message
      end

      def test_the_simulation_finds_the_papers_3_5_ms
        frames = [[1, 2.5], [2, 3.5], [3, 3.5]].map do |id, period|
          SimFrame.new(id, 1000, (period * 1000).to_i, 0) # 1 ms frames, 1 us bits
        end
        assert_equal([2000, 3000, 3500], (0..2).map { |i| simulate(frames, i, 20_000) })
      end
    end
  end
end
