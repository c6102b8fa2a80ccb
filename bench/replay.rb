# frozen_string_literal: true

# Measures the bus traffic tools: dispatching frames through a 64-device bus
# and replaying a 1,000,000-frame candump log end to end (parse, count,
# report), beside two peers on the same log when they are installed:
# python-can (bench/python_can_replay.py: its CanutilsLogReader, and a dict
# per mask for the same filters) and can-utils' log2asc (C). Run as
# `ruby -Ilib bench/replay.rb [FRAMES]`; bench/run.rb calls
# Syskit::Bench::Replay.run. Figures are measured on each run, never stored.

require 'benchmark'
require 'json'
require 'open3'
require 'tmpdir'
require 'syskit'
require 'syskit/bus/dispatcher'
require 'syskit/bus/replay'
require_relative 'replay_peers'
require_relative 'replay_app'

module Syskit
  module Bench
    # The replay benchmark: a synthetic bus and log, then timings.
    module Replay
      FRAMES = 1_000_000
      DEVICES = 64
      TARGETS = { dispatch: 500_000, end_to_end: 200_000 }.freeze
      # The replay against its peers: at least this many times python-can's
      # throughput, at most this many times log2asc's time.
      PYTHON_CAN_FACTOR = 2.5
      LOG2ASC_FACTOR = 1.25
      PEER_RUNS = 3
      PYTHON_CAN = File.join(__dir__, 'python_can_replay.py')

      module_function

      # Runs the benchmark and prints a table on +io+; returns the figures
      # (frames per second by measure).
      def run(io = $stdout, frames: FRAMES)
        devices = bus_devices
        dispatcher = Syskit::Bus::Dispatcher.new('can0', devices)
        random = Random.new(42)
        pool = id_pool(random)
        keys = Array.new(frames) { pool[random.rand(pool.size)] }
        results = measure_dispatch(dispatcher, keys)
        Dir.mktmpdir('syskit-bench') do |dir|
          path = write_log(File.join(dir, 'can0.log'), keys, random)
          # The keys are garbage from here: keeping them would make every GC
          # of the replay mark a million-entry array.
          keys = nil
          results.update(measure_replay(devices, path, frames))
          results[:peers] = Peers.new(dispatcher, path, results[:replay]).measure
        end
        print_table(io, frames, dispatcher, pool.size, results)
        Peers.print(io, results[:peers])
        results
      end

      # Dispatch alone: cached, per-mask lookups, and the linear scan the
      # dispatcher replaces (on a tenth of the frames: it is slow).
      def measure_dispatch(dispatcher, keys)
        scan = LinearScan.new(dispatcher)
        tenth = keys.first(keys.size / 10)
        { dispatch: best_rate(keys.size) { keys.each { |k| dispatcher.receivers(k) } },
          dispatch_uncached: best_rate(keys.size) { keys.each { |k| dispatcher.lookup(k) } },
          linear_scan: best_rate(tenth.size) { tenth.each { |k| scan.receivers(k) } } }
      end

      # Parse + count + report of the log at +path+, as `syskit bus replay`:
      # the best wall and CPU time of PEER_RUNS runs, and the report.
      def measure_replay(devices, path, frames)
        report = nil
        runs = Array.new(PEER_RUNS) do
          GC.start
          timed do
            report = Syskit::Bus::Replay.new(Syskit::Bus::Dispatcher.new('can0', devices), path,
                                             progress_out: nil).run
          end
        end
        replay = { wall: runs.map(&:first).min, cpu: runs.map(&:last).min, report: report }
        { end_to_end: frames / replay[:wall], log_mb: File.size(path) / 1e6, replay: replay }
      end

      # [wall, CPU] seconds of the block, in this process.
      def timed
        wall = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        cpu = Process.clock_gettime(Process::CLOCK_PROCESS_CPUTIME_ID)
        yield
        [Process.clock_gettime(Process::CLOCK_MONOTONIC) - wall,
         Process.clock_gettime(Process::CLOCK_PROCESS_CPUTIME_ID) - cpu]
      end

      # Frames per second of the block over +frames+ frames, the best of
      # +runs+ runs (other processes only ever make a run slower).
      def best_rate(frames, runs: 3, &block)
        Array.new(runs) do
          GC.start
          frames / Benchmark.realtime(&block)
        end.max
      end

      # What the dispatcher replaces, for reference: every filter tested
      # against every frame.
      class LinearScan
        def initialize(dispatcher)
          @filters = dispatcher.devices.select { |d| d.status == :filtered }.map { |d| [d.name, d.can_filter] }
        end

        def receivers(key)
          extended = key & Syskit::Bus::Frame::EFF_FLAG != 0
          id = key & Syskit::Bus::Frame::EFF_MASK
          @filters.select { |_, f| f.extended? == extended && f.match?(id) }.map(&:first)
        end
      end

      # 64 devices as a plan lists them: standard and extended filters with
      # a handful of distinct masks, as on a real robot, two write-only.
      def bus_devices
        filters = Array.new(24) { |i| [0x100 + (i * 0x10), 0x7F0] } +
                  Array.new(8) { |i| [0x600 + i, 0x7FF] } +
                  Array.new(6) { |i| [0x080 * i, 0x780] } +
                  Array.new(16) { |i| [0xFEF000 + (i << 8), 0x3FFFF00] } +
                  Array.new(8) { |i| [0x18FF0000 + i, 0x1FFFFFFF] }
        devices = filters.each_with_index.map do |(id, mask), i|
          plan_device("dev#{format('%02d', i)}", true, 'can_id' => [id, mask])
        end
        devices << plan_device('sync', false, 'can_id' => [0x080, 0x7FF])
        devices << plan_device('heartbeat', false, {})
        devices.first(DEVICES)
      end

      def plan_device(name, bus_to_client, attributes)
        Network::Plan::Device.with(name: name, bus: 'can0', bus_to_client: bus_to_client, client_to_bus: true,
                                   attributes: attributes)
      end

      # 600 distinct keys: 70 % standard, 30 % extended, some unclaimed.
      def id_pool(random)
        standard = Array.new(420) { random.rand(0x800) }
        extended = Array.new(180) do
          random.rand(4).zero? ? random.rand(0x2000_0000) : 0x18FE_F000 + random.rand(0x1_1000)
        end
        (standard + extended.map { |id| id | Syskit::Bus::Frame::EFF_FLAG }).uniq
      end

      def write_log(path, keys, random)
        time = 1_436_509_053_000_000
        File.open(path, 'w') do |f|
          keys.each do |key|
            time += 50 + random.rand(100)
            f.write(format('(%<s>010d.%<us>06d) can0 %<frame>s', s: time / 1_000_000, us: time % 1_000_000,
                                                                 frame: frame_text(key, random)), "\n")
          end
        end
        path
      end

      def frame_text(key, random)
        id = Syskit::Bus::Frame.key_to_s(key)
        kind = random.rand(100)
        return "#{id}#R" if kind.zero?
        return "#{id}##1#{'AB' * 12}" if kind < 3

        "#{id}##{'5A' * random.rand(9)}"
      end

      def print_table(io, frames, dispatcher, pool, results)
        io.puts "bus replay: #{frames} frames, #{DEVICES} devices (#{dispatcher.mask_count} distinct masks), " \
                "#{pool} distinct ids, log #{format('%.1f', results[:log_mb])} MB"
        rows = [['dispatch (cached)', results[:dispatch], TARGETS[:dispatch]],
                ['dispatch (per-mask lookup only)', results[:dispatch_uncached], TARGETS[:dispatch]],
                ['dispatch (linear scan, reference)', results[:linear_scan], nil],
                ['end to end (parse + count + report)', results[:end_to_end], TARGETS[:end_to_end]]]
        # The columns of the rows' format below.
        io.puts '  measure (best run)                         frames/s      target'
        rows.each do |what, value, target|
          verdict = target && (value >= target ? 'ok' : 'BELOW TARGET')
          line = format('  %-38<what>s %12<rate>d  %10<target>s  %<ok>s',
                        what: what, rate: value, target: target || '-', ok: verdict)
          io.puts line.rstrip
        end
      end
    end
  end
end

if $PROGRAM_NAME == __FILE__
  Syskit::Bench::Replay.run($stdout,
                            frames: Integer(ARGV.first || Syskit::Bench::Replay::FRAMES))
end
