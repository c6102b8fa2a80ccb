# frozen_string_literal: true

# Measures the CAN timing analysis: 2,000 frames on one 1 Mbit/s bus
# in-process, its scaling from 250 to 8,000 frames, and the whole
# `syskit bus timing` process on an app declaring 2,000 frames. Run as
# `ruby -Ilib bench/can_timing.rb`; bench/run.rb calls
# Syskit::Bench::CanTiming.run. Figures are measured on each run, never stored.

require 'fileutils'
require 'open3'
require 'rbconfig'
require 'tmpdir'
require 'syskit'
require 'syskit/can/timing'
require_relative 'growth'

module Syskit
  module Bench
    # The timing benchmark: synthetic frame sets, then timings.
    module CanTiming
      FRAMES = 2000
      SIZES = [250, 500, 1000, 2000, 4000, 8000].freeze
      BITRATE = 1_000_000
      TARGETS = { in_process: 0.5, process: 2.0 }.freeze
      # Periods and jitters of the synthetic frames, in ms (for 2,000 frames:
      # bigger sets get proportionally longer periods, so that the load of
      # the bus, about 66 %, is the same at every size).
      PERIODS_MS = [100, 200, 500, 1000, 2000, 5000].freeze
      JITTERS_MS = [0, 0, 0, 0.5, 1].freeze
      BIN = File.expand_path('../bin/syskit', __dir__)

      module_function

      # Sizes of the worst case, every frame with a period of its own.
      DISTINCT_SIZES = [500, 1000, 2000].freeze

      def run(io = $stdout)
        results = SIZES.to_h { |n| [n, best_time(frames(n))] }
        distinct = DISTINCT_SIZES.to_h { |n| [n, best_time(frames(n, distinct: true))] }
        process = Dir.mktmpdir('syskit-bench') { |dir| process_time(write_app(dir, FRAMES)) }
        print_table(io, results, 'a few periods and jitters, as robots have')
        print_table(io, distinct, 'the worst case, a period per frame')
        print_targets(io, results[FRAMES][:time], process)
        results
      end

      # +count+ frames: mixed standard and extended ids, 0-8 bytes, the
      # periods and jitters above (or, +distinct+, a period of its own for
      # each, in microseconds, from the same range); the same set on every run.
      def frames(count, distinct: false)
        random = Random.new(count)
        scale = Rational(count, FRAMES)
        random_ids(random, count).map do |id, extended|
          period = distinct ? distinct_period(random) : Rational(PERIODS_MS.sample(random: random), 1000)
          CAN::Timing::Frame.build(id: id, extended: extended, bytes: random.rand(0..8), period: period * scale,
                                   jitter: Rational(JITTERS_MS.sample(random: random).to_r, 1000), device: 'd')
        end
      end

      # A period from the range of PERIODS_MS, log-uniform (as many between
      # 100 and 200 ms as between 1 and 2 s), to the microsecond.
      def distinct_period(random)
        low = PERIODS_MS.first * 1000
        Rational((low * ((PERIODS_MS.last * 1000.0 / low)**random.rand)).round, 1_000_000)
      end

      # Distinct identifiers, a quarter of them extended.
      def random_ids(random, count)
        ids = {}
        until ids.size == count
          extended = random.rand(4).zero? || ids.size >= 0x700
          id = extended ? random.rand(0x800..0x1FFF_FFFF) : random.rand(0..0x7FF)
          ids[[id, extended]] = true
        end
        ids.keys
      end

      # The best analysis of +frames+, in seconds, over at least +runs+ runs
      # and +seconds+ of them, with what it found.
      def best_time(frames, runs: 5, seconds: 0.5)
        times = []
        result = nil
        until times.size >= runs && times.sum >= seconds
          start = Process.clock_gettime(Process::CLOCK_MONOTONIC)
          result = CAN::Timing::Analysis.run(bitrate: BITRATE, frames: frames)
          times << (Process.clock_gettime(Process::CLOCK_MONOTONIC) - start)
        end
        { time: times.min, runs: times.size, utilization: result.utilization,
          schedulable: result.frames.count(&:schedulable?) }
      end

      # An app whose profile declares +count+ frames on can0, four per device.
      def write_app(dir, count)
        devices = frames(count).each_slice(4).with_index.map do |slice, i|
          calls = slice.map do |f|
            "      .frame(0x#{f.id.to_s(16)}, bytes: #{f.bytes}, period: #{f.period.to_f}, " \
              "jitter: #{f.jitter.to_f}, extended: #{f.extended})"
          end
          "    device(Devices::Node, as: 'node#{i}')\n#{calls.join("\n")}"
        end
        file(dir, 'config/syskit.yml', "name: Bench\n")
        # The timing comes from the profile's declared frames: the robot
        # deploys nothing.
        file(dir, 'config/robots/default.rb', "# nothing deployed\n")
        file(dir, 'models/devices/node.rb', "module Bench\n  module Devices\n    device_type 'Node'\n  end\nend\n")
        file(dir, 'models/orogen/node.orogen', "name 'node'\nimport_types_from 'canbus'\ntask_context 'Task' do\n  " \
                                               "input_port 'can_in', '/canbus/Message'\n  " \
                                               "output_port 'can_out', '/canbus/Message'\nend\n")
        file(dir, 'models/orogen/node.rb', 'Syskit.extend_model(OroGen.node.Task) { driver_for Bench::Devices::Node, ' \
                                           "as: 'node' }\n")
        file(dir, 'models/profiles/base.rb', "using_task_library 'canbus'\nusing_task_library 'node'\n" \
                                             "profile 'Base' do\n  robot do\n    com_bus(CommonModels::Devices::Bus::" \
                                             "CAN, as: 'can0').bitrate(#{BITRATE})\n    through 'can0' do\n" \
                                             "#{devices.join("\n")}\n    end\n  end\nend\n")
        dir
      end

      def file(dir, path, content)
        FileUtils.mkdir_p(File.dirname(File.join(dir, path)))
        File.write(File.join(dir, path), content)
      end

      # The best of three whole `syskit bus timing --format json` processes.
      def process_time(app)
        Array.new(3) do
          start = Process.clock_gettime(Process::CLOCK_MONOTONIC)
          _, err, status = Open3.capture3(RbConfig.ruby, BIN, 'bus', 'timing', 'Base', '--bus', 'can0', '--app', app,
                                          '--format', 'json')
          # Exit status 1 says that frames miss their deadline, as some of
          # these do; anything on stderr is a failure.
          raise "syskit bus timing failed on #{app}: #{err}" unless status.exitstatus <= 1 && err.empty?

          Process.clock_gettime(Process::CLOCK_MONOTONIC) - start
        end.min
      end

      def print_table(io, results, what)
        io.puts "CAN timing analysis, one #{CAN::Timing::Format.bitrate(BITRATE)} bus: #{what} " \
                '(best of 5+ runs, 0.5 s+)'
        # Identifiers are drawn at random, not by deadline: some frames miss.
        io.puts '   frames  utilisation  meet deadline  runs  analysis s'
        results.each do |n, r|
          io.puts format('%<n>9d  %<u>10.1f %%  %<ok>13d  %<runs>4d  %<s>10.4f',
                         n: n, u: r[:utilization] * 100, ok: r[:schedulable], runs: r[:runs], s: r[:time])
        end
        print_exponents(io, results)
      end

      # log(t(m) / t(n)) / log(m / n) between consecutive sizes.
      def print_exponents(io, results)
        exponents = results.each_cons(2).to_h do |(small, a), (large, b)|
          ["#{small} -> #{large}", Growth.exponent(small, a[:time], large, b[:time])]
        end
        pairs = exponents.map { |name, e| "#{name} #{format('%.2f', e)}" }
        io.puts "  scaling exponent (1.0 is linear, 2.0 quadratic): #{pairs.join(', ')}; #{Growth.verdict(exponents)}"
      end

      def print_targets(io, in_process, process)
        io.puts '  measure                                         s      target'
        [["analysis of #{FRAMES} frames, in process", in_process, TARGETS[:in_process]],
         ["syskit bus timing on #{FRAMES} frames, whole process", process, TARGETS[:process]]].each do |what, s, target|
          io.puts format('  %-42<what>s %6.3<s>f  %6.1<target>f  %<ok>s', what: what, s: s, target: target,
                                                                          ok: s < target ? 'ok' : 'SLOW')
        end
      end
    end
  end
end

Syskit::Bench::CanTiming.run if $PROGRAM_NAME == __FILE__
