# frozen_string_literal: true

require 'syskit/can/timing/frame'
require 'syskit/can/timing/result'

module Syskit
  module CAN
    module Timing
      # The worst-case response time of every frame of a CAN bus: the
      # revised analysis of Davis, Burns, Bril and Lukkien, "Controller Area
      # Network (CAN) schedulability analysis: Refuted, revisited and
      # revised", Real-Time Systems 35:239-272 (2007).
      #
      # For frame m, in priority order (Frame#arbitration_key):
      #   C_m = bits * tau_bit                 transmission time
      #   B_m = max C_k over lower-priority k  blocking (a frame already on the wire)
      #   t_m = B_m + sum over hp(m) and m of ceil((t_m + J_k) / T_k) * C_k
      #                                        level-m busy period
      #   Q_m = ceil((t_m + J_m) / T_m)        instances queued in it
      #   w_m(q) = B_m + q * C_m + sum over hp(m) of ceil((w_m(q) + J_k + tau_bit) / T_k) * C_k
      #   R_m = max over q < Q_m of J_m + w_m(q) - q * T_m + C_m
      # The 1994 analysis stops at q = 0, which is optimistic: a later
      # instance of the busy period can take longer (see the README).
      #
      # Arithmetic is exact: every time is an integer count of ticks, the
      # tick being 1 / (least common multiple of the denominators of tau_bit
      # and of every period, deadline and jitter); results are Rationals.
      # A priority level whose utilisation is 1 or more has no busy period
      # bound: its frames and all lower ones are reported unbounded, not
      # iterated.
      #
      # Higher-priority frames are summed by (period, jitter): each step of
      # a recurrence costs one term per distinct pair queued more than once
      # in the time it is computed for, not one per frame (see
      # HigherPriority), and each busy period starts from the previous
      # level's (it can only be longer).
      class Analysis
        # +bitrate+: bits per second (a positive Integer); +frames+: Frame values.
        def self.run(bitrate:, frames:)
          new(bitrate, frames).run
        end

        def initialize(bitrate, frames)
          unless bitrate.is_a?(Integer) && bitrate.positive?
            raise ArgumentError, "the bitrate must be a positive integer of bits per second, got #{bitrate.inspect}"
          end

          @bitrate = bitrate
          # Equal keys (one id sent by two devices, which `syskit check`
          # reports) are ordered by device and declaration, deterministically.
          @frames = frames.each_with_index.sort_by { |f, i| [f.arbitration_key, f.device.to_s, i] }.map(&:first)
          @ticks_per_second = ticks_per_second
          @tau = @ticks_per_second / bitrate
        end

        # The BusResult.
        def run
          costs = @frames.map { |f| f.bits * @tau }
          blocking = blocking_times(costs)
          higher = HigherPriority.new
          utilization = 0r
          busy = 0
          results = @frames.each_with_index.map do |frame, index|
            utilization += Rational(frame.bits, @bitrate) / frame.period
            level = [frame, costs[index], blocking[index], higher]
            # From 100 % on, this level and every lower one have no bound.
            if utilization < 1
              busy = busy_period(*level, busy)
              times = response(*level, busy)
            end
            higher.add(ticks(frame.period), ticks(frame.jitter), costs[index])
            result(*level.first(3), times)
          end
          BusResult.new(bitrate: @bitrate, utilization: utilization, frames: results.freeze).freeze
        end

        private

        # Sums of C_k by (T_k, J_k) over the frames analysed so far: the
        # inner loop of the analysis.
        #
        # A pair whose T_k - J_k is at least the time asked for has one
        # instance queued by then: it adds exactly its C_k, which #total
        # already holds. Pairs are kept sorted by T_k - J_k in parallel
        # arrays, so only those queued more than once are visited, with a
        # while loop that stops at the first pair beyond the time.
        class HigherPriority
          attr_reader :total

          def initialize
            @pairs = {}
            @slack = []
            @periods = []
            @jitters = []
            @costs = []
            @total = 0
          end

          # Adds a frame of cost C_k to the pair (T_k, J_k), in ticks.
          def add(period, jitter, cost)
            slack = period - jitter
            i = @slack.bsearch_index { |s| s >= slack } || @slack.size
            if @pairs[[period, jitter]]
              i += 1 until @periods[i] == period && @jitters[i] == jitter
              @costs[i] += cost
            else
              @pairs[[period, jitter]] = true
              @slack.insert(i, slack)
              @periods.insert(i, period)
              @jitters.insert(i, jitter)
              @costs.insert(i, cost)
            end
            @total += cost
          end

          # The sum of ceil((time + J_k) / T_k) * C_k, time > 0.
          def interference(time)
            sum = @total
            i = 0
            n = @slack.size
            while i < n && @slack[i] < time
              sum -= ((-(time + @jitters[i]) / @periods[i]) + 1) * @costs[i]
              i += 1
            end
            sum
          end
        end

        # B_m: the longest frame of lower priority (0 for the lowest).
        def blocking_times(costs)
          longest = 0
          costs.reverse.map { |c| longest.tap { longest = [longest, c].max } }.reverse
        end

        # t_m, iterated from the previous level's busy period: level m adds
        # frame m's own term (at least C_m) and loses at most C_m of
        # blocking, so its busy period is no shorter.
        def busy_period(frame, cost, blocking, higher, previous)
          period = ticks(frame.period)
          jitter = ticks(frame.jitter)
          time = [previous, cost].max
          loop do
            own = -(-(time + jitter) / period) * cost
            following = blocking + higher.interference(time) + own
            return time if following == time

            time = following
          end
        end

        # [R_m, R_m(0), the worst q, Q_m], times in ticks.
        def response(frame, cost, blocking, higher, busy)
          period = ticks(frame.period)
          jitter = ticks(frame.jitter)
          instances = -(-(busy + jitter) / period)
          responses = []
          start = blocking + higher.total
          instances.times do |instance|
            start = queuing_delay(instance, cost, blocking, higher, start)
            responses << (jitter + start - (instance * period) + cost)
            start += cost
          end
          worst = responses.max
          [worst, responses.first, responses.index(worst), instances]
        end

        # w_m(q), the least fixed point from +start+ (w_m(q) >= w_m(q-1) + C_m).
        def queuing_delay(instance, cost, blocking, higher, start)
          base = blocking + (instance * cost)
          time = [start, base + higher.total].max
          loop do
            following = base + higher.interference(time + @tau)
            return time if following == time

            time = following
          end
        end

        def result(frame, cost, blocking, response)
          worst, first, worst_instance, instances = response
          FrameResult.new(
            frame: frame, transmission_time: seconds(cost), blocking: seconds(blocking),
            response_time: worst && seconds(worst), original_response_time: first && seconds(first),
            worst_instance: worst_instance, instances: instances
          ).freeze
        end

        def ticks_per_second
          @frames.reduce(@bitrate) do |lcm, f|
            lcm.lcm(f.period.denominator).lcm(f.deadline.denominator).lcm(f.jitter.denominator)
          end
        end

        def ticks(seconds)
          (seconds * @ticks_per_second).to_i
        end

        def seconds(ticks)
          Rational(ticks, @ticks_per_second)
        end
      end
    end
  end
end
