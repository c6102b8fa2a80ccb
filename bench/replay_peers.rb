# frozen_string_literal: true

require 'json'
require 'open3'
require 'rbconfig'

module Syskit
  module Bench
    module Replay
      # The replay beside its peers on the same log and filters, every one
      # timed as a whole process without Bundler, start-up included, as a
      # user of the installed gem runs them (issue 40): `syskit bus replay`
      # on an app whose plan has the same devices (see App), python-can
      # (Debian's python3-can) through bench/python_can_replay.py, and
      # can-utils' log2asc (Debian's can-utils), a C program that reads the
      # log and writes it as ASC. The in-process figures of the replay and
      # of python-can (start-up and imports left out) are printed beside.
      class Peers
        # +wall+ and +cpu+: best seconds of the whole process; +inner+:
        # best seconds measured inside it, when known; +missing+: why it
        # was not measured.
        Result = Struct.new(:name, :wall, :cpu, :inner, :missing, :note, keyword_init: true)
        PYTHONS = [ENV.fetch('SYSKIT_BENCH_PYTHON', nil), 'python3', '/usr/bin/python3'].compact.uniq.freeze
        BIN = File.expand_path('../bin/syskit', __dir__)

        def initialize(dispatcher, path, replay)
          @dispatcher = dispatcher
          @path = path
          @replay = replay
        end

        def measure
          { syskit: syskit, python_can: python_can, log2asc: log2asc }
        end

        # `syskit bus replay --format json` of the log, whole process.
        def syskit
          app = App.write(File.join(File.dirname(@path), 'app'), Replay.bus_devices)
          command = [RbConfig.ruby, BIN, 'bus', 'replay', '--app', app, '--bus', 'can0', '--format', 'json', @path]
          # The first run compiles the app (see ISeqCache); it is not kept.
          capture(*command)
          runs = Array.new(PEER_RUNS) { timed_capture(*command) }
          received = JSON.parse(runs.last.last)['devices'].select { |d| d['frames'].positive? }
                                                          .to_h { |d| [d['name'], d['frames']] }
          Result.new(name: 'syskit bus replay', wall: runs.map(&:first).min, cpu: runs.map { |r| r[1] }.min,
                     inner: @replay[:wall], note: same_counts(received))
        end

        def python_can
          python = PYTHONS.find { |py| quiet_system(py, '-c', 'import can') }
          unless python
            return Result.new(name: 'python-can', missing: 'not installed (Debian: apt-get install python3-can)')
          end

          version, = Open3.capture2(python, '-c', 'import can; print(can.__version__)')
          filters = write_filters
          runs = Array.new(PEER_RUNS) { timed_capture(python, PYTHON_CAN, @path, filters) }
          inside = runs.map { |r| JSON.parse(r.last) }
          Result.new(name: "python-can #{version.strip}", wall: runs.map(&:first).min, cpu: runs.map { |r| r[1] }.min,
                     inner: inside.map { |r| r['seconds'] }.min, note: same_counts(inside.last['received']))
        end

        def log2asc
          unless quiet_system('sh', '-c', 'command -v log2asc')
            return Result.new(name: 'can-utils log2asc', missing: 'not installed (Debian: apt-get install can-utils)')
          end

          runs = Array.new(PEER_RUNS) { process_times('log2asc', '-I', @path, '-O', File::NULL, 'can0') }
          Result.new(name: 'can-utils log2asc (C)', wall: runs.map(&:first).min, cpu: runs.map(&:last).min)
        end

        # The filters of the dispatcher's receiving devices, for the script.
        def write_filters
          path = File.join(File.dirname(@path), 'filters.json')
          filters = @dispatcher.devices.select { |d| d.status == :filtered }.map do |d|
            [d.name, d.can_filter.id, d.can_filter.mask, d.can_filter.extended?]
          end
          File.write(path, JSON.generate(filters))
          path
        end

        # Whether the peer found what the replay found: the frames each
        # device receives.
        def same_counts(received)
          ours = @replay[:report].devices.select { |d| d.frames.positive? }.to_h { |d| [d.name, d.frames] }
          ours == received ? 'same frames per device' : 'DIFFERENT frames per device: not the same work'
        end

        # [wall, CPU, standard output] of a whole process.
        def timed_capture(*command)
          before = Process.times
          start = Process.clock_gettime(Process::CLOCK_MONOTONIC)
          out = capture(*command)
          after = Process.times
          [Process.clock_gettime(Process::CLOCK_MONOTONIC) - start,
           (after.cutime - before.cutime) + (after.cstime - before.cstime), out]
        end

        def capture(*command)
          out, status = Open3.capture2(*command)
          raise "#{command.join(' ')} failed (#{status})" unless status.success?

          out
        end

        # [wall, CPU] seconds of a whole process.
        def process_times(*command)
          before = Process.times
          start = Process.clock_gettime(Process::CLOCK_MONOTONIC)
          raise "#{command.join(' ')} failed" unless system(*command, out: File::NULL)

          after = Process.times
          [Process.clock_gettime(Process::CLOCK_MONOTONIC) - start,
           (after.cutime - before.cutime) + (after.cstime - before.cstime)]
        end

        def quiet_system(*command)
          system(*command, out: File::NULL, err: File::NULL)
        rescue SystemCallError
          false
        end

        def self.print(io, peers)
          io.puts 'replay beside its peers, on the same log and filters, whole processes without Bundler ' \
                  "(best of #{PEER_RUNS} runs; in process: the part timed inside it)"
          io.puts '  who                                   wall s   CPU s  in process s   ' \
                  'syskit bus replay        target'
          ours = peers[:syskit]
          print_peer(io, ours, nil)
          io.puts "    #{ours.note}"
          print_peer(io, peers[:python_can], ours)
          print_peer(io, peers[:log2asc], ours)
        end

        # python-can: the replay's throughput over the peer's (at least
        # PYTHON_CAN_FACTOR); log2asc: the replay's time over the peer's
        # (at most LOG2ASC_FACTOR); both whole processes.
        def self.print_peer(io, peer, ours)
          return io.puts("  #{peer.name}: #{peer.missing}; not measured") if peer.missing

          verdict = ours ? verdict(peer, ours) : ''
          inner = peer.inner ? format('%.3f', peer.inner) : '-'
          figures = { name: peer.name, wall: peer.wall, cpu: peer.cpu, inner: inner, verdict: verdict }
          line = format('  %-36<name>s %7.3<wall>f %7.3<cpu>f  %12<inner>s   %<verdict>s', figures)
          io.puts line.rstrip
          io.puts "    #{peer.note}" if peer.note && ours
        end

        def self.verdict(peer, ours)
          # The CPU ratio beside: on a busy machine wall times wait for a core.
          if peer.name.start_with?('python-can')
            ratio = peer.wall / ours.wall
            "#{format('%.2f', ratio)}x its frames/s (CPU #{format('%.2f', peer.cpu / ours.cpu)}x)  " \
              ">= #{PYTHON_CAN_FACTOR}x  #{ratio >= PYTHON_CAN_FACTOR ? 'ok' : 'BELOW TARGET'}"
          else
            ratio = ours.wall / peer.wall
            "#{format('%.2f', ratio)}x its time (CPU #{format('%.2f', ours.cpu / peer.cpu)}x)      " \
              "<= #{LOG2ASC_FACTOR}x  #{ratio <= LOG2ASC_FACTOR ? 'ok' : 'ABOVE TARGET'}"
          end
        end
      end
    end
  end
end
