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
          reader, writer = IO.pipe
          pid = fork do
            reader.close
            writer.write(JSON.generate(in_process(app_dir, devices)))
            writer.close
            exit!(0)
          end
          writer.close
          row = JSON.parse(reader.read)
          Process.wait(pid)
          row.merge('process' => process_wall_time(app_dir))
        end
      end

      def in_process(app_dir, devices)
        GC.start
        app = App.new(app_dir)
        load_time, load_objects = measure { app.load!(robots: ['default']) }
        best = best_run(app, app.profiles.values.first)
        best.merge('devices' => devices, 'load' => load_time, 'load_objects' => load_objects, 'rss_mb' => peak_rss_mb)
      end

      # Each figure is the best of the runs, the usual way to keep other
      # processes' noise out.
      def best_run(app, profile)
        runs = []
        started = now
        runs << one_run(app, profile) while runs.size < RUNS || now - started < SECONDS
        runs.first.keys.to_h { |k| [k, runs.map { |r| r[k] }.min] }.merge('runs' => runs.size)
      end

      def one_run(app, profile)
        result = nil
        time, objects = measure { result = Network::Generator.plan_profile(app, profile) }
        run = { 'generate' => time, 'objects' => objects }.merge(result.timings.slice(*PHASES))
        # Rendering as `syskit plan` does it: written to an IO (here the
        # null device, so the disk is not measured).
        File.open(File::NULL, 'w') do |null|
          RENDERERS.each { |name, renderer| run[name], = measure { renderer.write(result.plan, null) } }
        end
        run.merge('tasks' => result.plan.tasks.size)
      end

      def now
        Process.clock_gettime(Process::CLOCK_MONOTONIC)
      end

      def measure
        GC.start
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
      def print_exponents(out, rows)
        small = rows.find { |r| r['devices'] == 1000 }
        large = rows.find { |r| r['devices'] == 10_000 }
        return unless small && large

        keys = %w[load] + PHASES + %w[generate objects json text dot]
        factor = Math.log10(large['devices'].to_f / small['devices'])
        exponents = keys.map { |k| "#{k} #{format('%.2f', Math.log10(large[k] / small[k].to_f) / factor)}" }
        out.puts "scaling exponent 1,000 -> 10,000 devices: #{exponents.join(', ')}"
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
