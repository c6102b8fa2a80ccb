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
      # level's (it can only be longer). Of the Q_m instances, only those
      # that can hold the worst response are examined (#instances_needed:
      # their number does not grow with the jitter), and the first that
      # misses its deadline ends the frame's analysis; memory does not grow
      # with the instances.
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
            level = level(frame, costs[index], blocking[index])
            # From 100 % on, this level and every lower one have no bound.
            busy, times = analyse(level, higher, utilization, busy) if utilization < 1
            higher.add(level.period, level.jitter, level.cost)
            result(frame, level, times)
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
          # The sum of C_k; the least common multiple of the T_k (1 for none).
          attr_reader :total, :hyperperiod

          def initialize
            @pairs = {}
            @slack = []
            @periods = []
            @jitters = []
            @costs = []
            @total = 0
            @hyperperiod = 1
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
            @hyperperiod = @hyperperiod.lcm(period)
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

        # Frame m's values in ticks.
        Level = Struct.new(:period, :jitter, :deadline, :cost, :blocking)

        # What the analysis of one frame found, in ticks: R_m, R_m(0), the
        # q of the worst instance, the instances examined, and whether it
        # stopped at one that misses its deadline.
        Response = Struct.new(:worst, :first_instance, :worst_instance, :examined, :stopped_at_miss)

        def level(frame, cost, blocking)
          Level.new(ticks(frame.period), ticks(frame.jitter), ticks(frame.deadline), cost, blocking)
        end

        # [t_m, the Response] of one level, whose utilisation is below 1.
        def analyse(level, higher, utilization, previous_busy)
          needed = instances_needed(level, higher, utilization)
          busy, queued = busy_period(level, higher, previous_busy, needed)
          [busy, response(level, higher, [queued, needed].min)]
        end

        # B_m: the longest frame of lower priority (0 for the lowest).
        def blocking_times(costs)
          longest = 0
          costs.reverse.map { |c| longest.tap { longest = [longest, c].max } }.reverse
        end

        # How many instances of the busy period can hold the worst
        # response, whatever the jitters: the response of instance q is
        # R_m(q) = J_m + C_m + w_m(q) - q * T_m, and J_m does not change
        # w_m, so a large jitter only adds instances that respond no later:
        # - bounding each ceil by its argument and its argument + 1 gives
        #   w_m(q) - q * T_m <= w_m(0) + (sum of hp C_k - q * T_m * (1 - U)) / (1 - U_hp),
        #   U the level's utilisation: no instance from
        #   ceil(sum of hp C_k / (T_m * (1 - U))) on responds later than the first;
        # - with H the least common multiple of the level's periods, a
        #   pre-fixed point argument gives w_m(q + H / T_m) <= w_m(q) + H:
        #   instance q + H / T_m responds no later than instance q.
        # So the analysis needs at most the smaller of the two, and never
        # more than the instances queued (Q_m); the time and memory it
        # takes do not grow with the jitter.
        def instances_needed(level, higher, utilization)
          by_load = (Rational(higher.total) / (level.period * (1 - utilization))).ceil
          by_hyperperiod = higher.hyperperiod.lcm(level.period) / level.period
          by_load.clamp(1, by_hyperperiod)
        end

        # [t_m, Q_m], t_m iterated from the previous level's busy period:
        # level m adds frame m's own term (at least C_m) and loses at most
        # C_m of blocking, so its busy period is no shorter. Stops as soon
        # as +needed+ instances are queued in it: the instances after them
        # are not analysed, and a busy period iterated from below is still
        # a lower bound for the next level.
        def busy_period(level, higher, previous, needed)
          time = [previous, level.cost].max
          loop do
            queued = -(-(time + level.jitter) / level.period)
            following = level.blocking + higher.interference(time) + (queued * level.cost)
            return [time, queued] if following == time || queued >= needed

            time = following
          end
        end

        # R_m as the maximum over the first +instances+ instances, kept as
        # it goes (memory does not grow with the instances). The first
        # instance that misses its deadline ends the search: the frame
        # misses, and its worst response is at least that one's.
        def response(level, higher, instances)
          found = Response.new(nil, nil, nil, 0, false)
          start = level.blocking + higher.total
          instances.times do |instance|
            start = queuing_delay(instance, level, higher, start)
            time = level.jitter + start - (instance * level.period) + level.cost
            found.first_instance ||= time
            if found.worst.nil? || time > found.worst
              found.worst = time
              found.worst_instance = instance
            end
            found.examined = instance + 1
            break found.stopped_at_miss = found.examined < instances if time > level.deadline

            start += level.cost
          end
          found
        end

        # w_m(q), the least fixed point from +start+ (w_m(q) >= w_m(q-1) + C_m).
        def queuing_delay(instance, level, higher, start)
          base = level.blocking + (instance * level.cost)
          time = [start, base + higher.total].max
          loop do
            following = base + higher.interference(time + @tau)
            return time if following == time

            time = following
          end
        end

        def result(frame, level, response)
          FrameResult.new(
            frame: frame, transmission_time: seconds(level.cost), blocking: seconds(level.blocking),
            response_time: response && seconds(response.worst),
            original_response_time: response && seconds(response.first_instance),
            worst_instance: response&.worst_instance, instances: response&.examined,
            stopped_at_miss: response ? response.stopped_at_miss : false
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
