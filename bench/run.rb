# frozen_string_literal: true

# rake bench: load, generation (each phase) and rendering times, allocated
# objects and peak RSS on synthetic robots of 100, 1,000 and 10,000 devices,
# the wall time of the whole `syskit plan --format json` process, and the
# scaling exponent between 1,000 and 10,000 devices. Every figure printed is
# measured on this run.

require 'json'
require 'rbconfig'
require 'tmpdir'
require 'syskit'
require 'syskit/render/json'
require 'syskit/render/text'
require 'syskit/render/dot'
require_relative 'synthetic_app'

module Syskit
  module Bench
    # Runs the generation benchmark and prints its table.
    module Generation
      SIZES = (ENV['SYSKIT_BENCH_SIZES'] || '100,1000,10000').split(',').map { |s| Integer(s) }
      PHASES = %w[drivers buses deploy order configure connect plan].freeze
      RENDERERS = { 'json' => Render::JSON, 'text' => Render::Text, 'dot' => Render::Dot }.freeze
      # Each size runs generation and rendering at least RUNS times and for
      # at least SECONDS: small robots get many runs, so their best is not a
      # moment of a noisy machine.
      RUNS = Integer(ENV.fetch('SYSKIT_BENCH_RUNS', '5'))
      SECONDS = Float(ENV.fetch('SYSKIT_BENCH_SECONDS', '2'))
      # The CPU caches are emptied by reading a buffer larger than the
      # last-level cache (32 MB on the machine of the README's figures).
      EVICTION_MB = Integer(ENV.fetch('SYSKIT_BENCH_EVICTION_MB', '128'))
      # Loading and the whole `syskit plan` process happen once per process:
      # each is measured in this many fresh processes, best kept.
      PROCESS_RUNS = Integer(ENV.fetch('SYSKIT_BENCH_PROCESS_RUNS', '3'))
      BIN = File.expand_path('../bin/syskit', __dir__)

      module_function

      def run(out = $stdout)
        out.puts "Network generation on #{RUBY_DESCRIPTION} " \
                 "(best of at least #{RUNS} runs and #{SECONDS} s per size)"
        rows = SIZES.map { |n| measure_size(n) }
        print_table(out, rows)
        print_exponents(out, rows)
        rows
      end

      # Measures one size in a child process, so its peak RSS is its own.
      def measure_size(devices)
        Dir.mktmpdir('syskit-bench') do |dir|
          app_dir = SyntheticApp.write(File.join(dir, 'bench'), devices)
          row = in_child { in_process(app_dir, devices) }
          loads = Array.new(PROCESS_RUNS - 1) { in_child { load_app(App.new(app_dir)).first } }
          row.merge('load' => [row['load'], *loads].min,
                    'process' => Array.new(PROCESS_RUNS) { process_wall_time(app_dir) }.min)
        end
      end

      # The block's value, computed in a child process.
      def in_child
        reader, writer = IO.pipe
        pid = fork do
          reader.close
          writer.write(JSON.generate(yield))
          writer.close
          exit!(0)
        end
        writer.close
        output = reader.read
        reader.close
        _, status = Process.wait2(pid)
        raise "a benchmark process failed (#{status})" unless status.success?

        JSON.parse(output)
      end

      def load_app(app)
        GC.start
        measure { app.load!(robots: ['default']) }
      end

      def in_process(app_dir, devices)
        app = App.new(app_dir)
        load_time, load_objects = load_app(app)
        profile = app.profiles.values.first
        row = best_run(app, profile)
        # Peak RSS before the cold runs allocate their eviction buffer.
        row.merge!('devices' => devices, 'load' => load_time, 'load_objects' => load_objects, 'rss_mb' => peak_rss_mb)
        row.merge(cold_run(app, profile).transform_keys { |k| "cold #{k}" })
      end

      # Each figure is the best of the runs, the usual way to keep other
      # processes' noise out.
      def best_run(app, profile)
        runs = []
        started = now
        runs << one_run(app, profile) while runs.size < RUNS || now - started < SECONDS
        best(runs).merge('runs' => runs.size)
      end

      def best(runs)
        runs.first.keys.to_h { |k| [k, runs.map { |r| r[k] }.min] }
      end

      def one_run(app, profile, empty_caches = nil)
        result = nil
        time, objects = measure { result = Network::Generator.plan_profile(app, profile, before_step: empty_caches) }
        run = { 'generate' => time, 'objects' => objects }.merge(result.timings.slice(*PHASES))
        # Rendering as `syskit plan` does it: written to an IO (here the
        # null device, so the disk is not measured).
        File.open(File::NULL, 'w') do |null|
          RENDERERS.each do |name, renderer|
            run[name], = measure(empty_caches) { renderer.write(result.plan, null) }
          end
        end
        run.merge('tasks' => result.plan.tasks.size)
      end

      # The runs again with the CPU caches emptied before each phase: 1,000
      # devices then start from memory as 10,000 do, and the exponent
      # between them shows how the work grows rather than what fits in the
      # caches. (A warm 1,000-device network fits in them; 10,000 does not.)
      def cold_run(app, profile)
        buffer = "\1" * (EVICTION_MB << 20)
        empty_caches = -> { buffer.sum }
        best(Array.new(RUNS) { one_run(app, profile, empty_caches) }).slice(*PHASES, *RENDERERS.keys)
      end

      def now
        Process.clock_gettime(Process::CLOCK_MONOTONIC)
      end

      def measure(before = nil)
        GC.start
        before&.call
        objects = GC.stat(:total_allocated_objects)
        start = now
        yield
        [now - start, GC.stat(:total_allocated_objects) - objects]
      end

      def peak_rss_mb
        File.read('/proc/self/status')[/^VmHWM:\s+(\d+) kB/, 1].to_i / 1024.0
      end

      # The whole `syskit plan --format json` process, Ruby start-up included.
      def process_wall_time(app_dir)
        start = now
        ok = system(RbConfig.ruby, BIN, 'plan', '--app', app_dir, '--format', 'json', out: File::NULL)
        raise "syskit plan failed on #{app_dir}" unless ok

        now - start
      end

      COLUMNS = [['devices', 'devices', '%d'], ['tasks', 'tasks', '%d'], %w[runs runs %d], ['load', 'load s', '%.3f']] +
                PHASES.map { |p| [p, p, '%.4f'] } +
                [['generate', 'generate s', '%.3f'], %w[objects objects %d], ['json', 'json s', '%.3f'],
                 ['text', 'text s', '%.3f'], ['dot', 'dot s', '%.3f'], ['rss_mb', 'peak RSS MB', '%.0f'],
                 ['process', 'plan process s', '%.2f']].freeze

      def print_table(out, rows)
        cells = rows.map { |r| COLUMNS.map { |key, _, fmt| format(fmt, r.fetch(key)) } }
        widths = COLUMNS.each_with_index.map { |(_, title, _), i| ([title.size] + cells.map { |c| c[i].size }).max }
        out.puts COLUMNS.each_with_index.map { |(_, title, _), i| title.rjust(widths[i]) }.join('  ')
        cells.each { |c| out.puts c.each_with_index.map { |v, i| v.rjust(widths[i]) }.join('  ') }
      end

      # log10(t(10,000) / t(1,000)): 1.0 is linear, 2.0 quadratic.
      # Between consecutive sizes from 1,000 devices up (below that, fixed
      # costs dominate), as measured, then with the caches emptied.
      def print_exponents(out, rows)
        rows.sort_by { |r| r['devices'] }.each_cons(2) do |small, large|
          next if small['devices'] < 1000

          sizes = "#{delimited(small['devices'])} -> #{delimited(large['devices'])} devices"
          warm = %w[load] + PHASES + %w[generate objects] + RENDERERS.keys
          out.puts "scaling exponent #{sizes}: #{exponents(small, large, warm)}"
          cold = (PHASES + RENDERERS.keys).map { |k| "cold #{k}" }
          out.puts "  with the CPU caches emptied before each phase: #{exponents(small, large, cold)}"
        end
      end

      def exponents(small, large, keys)
        factor = Math.log10(large['devices'].to_f / small['devices'])
        keys.map do |k|
          "#{k.delete_prefix('cold ')} #{format('%.2f', Math.log10(large[k] / small[k].to_f) / factor)}"
        end.join(', ')
      end

      def delimited(number)
        number.to_s.reverse.scan(/\d{1,3}/).join(',').reverse
      end
    end
  end
end

if $PROGRAM_NAME == __FILE__
  Syskit::Bench::Generation.run
  replay = File.join(__dir__, 'replay.rb')
  if File.file?(replay)
    require replay
    puts
    Syskit::Bench::Replay.run if defined?(Syskit::Bench::Replay)
  end
end
