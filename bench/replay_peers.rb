# frozen_string_literal: true

require 'json'
require 'open3'

module Syskit
  module Bench
    module Replay
      # The replay's peers on the same log and filters, measured when they
      # are installed: python-can (Debian's python3-can) through
      # bench/python_can_replay.py, timed inside Python (start-up and
      # imports left out, as the replay is timed inside Ruby), and
      # can-utils' log2asc (Debian's can-utils), a C program that reads the
      # log and writes it as ASC, timed as a whole process.
      class Peers
        # +wall+ and +cpu+: best seconds; +missing+: why it was not measured.
        Result = Struct.new(:name, :wall, :cpu, :missing, :note, keyword_init: true)
        PYTHONS = [ENV.fetch('SYSKIT_BENCH_PYTHON', nil), 'python3', '/usr/bin/python3'].compact.uniq.freeze

        def initialize(dispatcher, path, replay)
          @dispatcher = dispatcher
          @path = path
          @replay = replay
        end

        def measure
          { python_can: python_can, log2asc: log2asc }
        end

        def python_can
          python = PYTHONS.find { |py| quiet_system(py, '-c', 'import can') }
          unless python
            return Result.new(name: 'python-can', missing: 'not installed (Debian: apt-get install python3-can)')
          end

          version, = Open3.capture2(python, '-c', 'import can; print(can.__version__)')
          filters = write_filters
          runs = Array.new(PEER_RUNS) { JSON.parse(capture(python, PYTHON_CAN, @path, filters)) }
          Result.new(name: "python-can #{version.strip} (in process)", wall: runs.map { |r| r['seconds'] }.min,
                     cpu: runs.map { |r| r['cpu'] }.min, note: same_counts(runs.last['received']))
        end

        def log2asc
          unless quiet_system('sh', '-c', 'command -v log2asc')
            return Result.new(name: 'can-utils log2asc', missing: 'not installed (Debian: apt-get install can-utils)')
          end

          runs = Array.new(PEER_RUNS) { process_times('log2asc', '-I', @path, '-O', File::NULL, 'can0') }
          Result.new(name: 'can-utils log2asc (whole process, C)', wall: runs.map(&:first).min,
                     cpu: runs.map(&:last).min)
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

        def self.print(io, peers, replay)
          io.puts "replay beside its peers, on the same log and filters (best of #{PEER_RUNS} runs)"
          io.puts '  who                                        wall s   CPU s   syskit replay        target'
          io.puts format('  %-40<name>s %8.3<wall>f %7.3<cpu>f', name: 'syskit bus replay (in process)',
                                                                 wall: replay[:wall], cpu: replay[:cpu])
          print_peer(io, peers[:python_can], replay, :throughput)
          print_peer(io, peers[:log2asc], replay, :time)
        end

        # python-can: the replay's throughput over the peer's (at least
        # PYTHON_CAN_FACTOR); log2asc: the replay's time over the peer's
        # (at most LOG2ASC_FACTOR).
        def self.print_peer(io, peer, replay, measure)
          return io.puts("  #{peer.name}: #{peer.missing}; not measured") if peer.missing

          if measure == :throughput
            ratio = peer.wall / replay[:wall]
            verdict = "#{format('%.2f', ratio)}x its frames/s  >= #{PYTHON_CAN_FACTOR}x  " \
                      "#{ratio >= PYTHON_CAN_FACTOR ? 'ok' : 'BELOW TARGET'}"
          else
            ratio = replay[:wall] / peer.wall
            verdict = "#{format('%.2f', ratio)}x its time      <= #{LOG2ASC_FACTOR}x  " \
                      "#{ratio <= LOG2ASC_FACTOR ? 'ok' : 'ABOVE TARGET'}"
          end
          io.puts format('  %-40<name>s %8.3<wall>f %7.3<cpu>f   %<verdict>s', name: peer.name, wall: peer.wall,
                                                                               cpu: peer.cpu, verdict: verdict)
          io.puts "    #{peer.note}" if peer.note
        end
      end
    end
  end
end
