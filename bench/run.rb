# frozen_string_literal: true

# rake bench: start-up (bench/startup.rb); load, generation (each phase)
# and rendering times, allocated objects and peak RSS on synthetic robots of
# 1,000 to 10,000 devices, without and with compositions, the whole
# `syskit plan --format json` and `syskit check` processes, and the scaling
# exponents between sizes, with the CPU caches emptied before each phase and
# back to back; then the bus replay beside its peers (bench/replay.rb) and
# the CAN timing analysis (bench/can_timing.rb), and `syskit check` on
# configuration files of many unknown properties (bench/conf_check.rb). Every figure printed is
# measured on this run, with the machine's load average.

require 'json'
require 'rbconfig'
require 'tmpdir'
require_relative 'synthetic_app'
require_relative 'worker'
require_relative 'startup'
require_relative 'growth'
require_relative 'replay'
require_relative 'can_timing'
require_relative 'conf_check'

module Syskit
  # rake bench: see the top of this file.
  module Bench
    # The parts of `rake bench`, in the order they run; `rake bench
    # ONLY=replay,startup` (or SYSKIT_BENCH_ONLY) runs some of them.
    PARTS = {
      'startup' => -> { Startup.run },
      'generation' => -> { Generation.run },
      'compositions' => -> { Generation.run(compositions: true) },
      'replay' => -> { Replay.run },
      'timing' => -> { CanTiming.run },
      'conf' => -> { ConfCheck.run }
    }.freeze

    # The parts named in +only+ (comma-separated), all without it.
    def self.parts(only)
      return PARTS if only.nil? || only.empty?

      names = only.split(',').map(&:strip)
      unknown = names - PARTS.keys
      abort "rake bench: unknown part(s) #{unknown.join(', ')}; the parts: #{PARTS.keys.join(', ')}" if unknown.any?
      PARTS.slice(*names)
    end

    # Runs the generation benchmark and prints its table.
    module Generation
      SIZES = (ENV['SYSKIT_BENCH_SIZES'] || '1000,2000,5000,10000').split(',').map { |s| Integer(s) }
      # The whole `syskit plan --format json` process on robots without
      # compositions, in seconds, by devices (issue 40).
      PLAN_TARGETS = { 1000 => 0.2, 10_000 => 1.0 }.freeze
      # Objects allocated per device while loading and per task by the
      # first generation of a process (the slope between the smallest and
      # largest robots), as measured when issue 40 was filed (commit
      # 7d54c4f, the same measure); its target is half of each.
      OBJECTS_BEFORE = { 'load objects per device' => 83.7, 'generate objects per task' => 63.7 }.freeze
      PHASES = Worker::PHASES
      RENDERERS = Worker::RENDERERS.keys
      # Each size's worker is asked for ROUNDS rounds of runs, in turn, and
      # runs for at least ROUND_SECONDS each time: small robots get many
      # runs, large ones at least ROUNDS. Every figure is the best run.
      ROUNDS = Integer(ENV.fetch('SYSKIT_BENCH_ROUNDS', '5'))
      ROUND_SECONDS = Float(ENV.fetch('SYSKIT_BENCH_ROUND_SECONDS', '0.3'))
      # The CPU caches are emptied by reading a buffer larger than the
      # last-level cache (32 MB on the machine of the README's figures).
      EVICTION_MB = Integer(ENV.fetch('SYSKIT_BENCH_EVICTION_MB', '128'))
      # Loading and the whole `syskit plan` process happen once per process:
      # each is measured in this many fresh processes, best kept.
      PROCESS_RUNS = Integer(ENV.fetch('SYSKIT_BENCH_PROCESS_RUNS', '3'))
      BIN = File.expand_path('../bin/syskit', __dir__)

      module_function

      # The table of one kind of robot: devices alone, or +compositions+
      # (each device also used by a definition; see SyntheticApp).
      def run(out = $stdout, compositions: false)
        what = compositions ? 'devices used by compositions, one definition per device' : 'devices'
        out.puts "Network generation, #{what}, on #{RUBY_DESCRIPTION} " \
                 "(best of #{ROUNDS} interleaved rounds of at least #{ROUND_SECONDS} s per size)"
        rows = Dir.mktmpdir('syskit-bench') do |dir|
          apps = SIZES.to_h { |n| [n, SyntheticApp.write(File.join(dir, "bench#{n}"), n, compositions: compositions)] }
          measure_sizes(apps)
        end
        print_table(out, rows)
        print_exponents(out, rows)
        unless compositions
          print_targets(out, rows)
          print_objects(out, rows)
        end
        rows
      end

      # The whole processes of the sizes that have a target.
      def print_targets(out, rows)
        rows.sort_by { |r| r['devices'] }.each do |row|
          target = PLAN_TARGETS[row['devices']]
          next unless target

          out.puts format('syskit plan --format json of %<n>s devices, whole process: %<s>.2f s (CPU %<cpu>.2f s), ' \
                          'peak RSS %<rss>.0f MB, target %<t>.1f s: %<ok>s; syskit check: %<check>.2f s ' \
                          '(CPU %<check_cpu>.2f s)',
                          n: delimited(row['devices']), s: row['process'], cpu: row['process cpu'],
                          rss: row['rss_mb'], t: target, ok: row['process'] < target ? 'ok' : 'SLOWER',
                          check: row['check'], check_cpu: row['check cpu'])
        end
      end

      # Objects allocated per device (loading) and per task (generating),
      # in a fresh process as `syskit plan` allocates them: the slope
      # between the smallest and the largest robot, so that what every run
      # allocates whatever the robot is left out.
      def print_objects(out, rows)
        small, large = rows.minmax_by { |r| r['devices'] }
        return if small.equal?(large)

        { 'load objects per device' => %w[load_objects devices],
          'generate objects per task' => %w[first_generate_objects tasks] }.each do |what, (objects, per)|
          slope = (large[objects] - small[objects]).to_f / (large[per] - small[per])
          before = OBJECTS_BEFORE.fetch(what)
          out.puts format('%<what>s: %<slope>.1f (issue 40: %<before>.1f, target %<target>.1f): %<ok>s',
                          what: what, slope: slope, before: before, target: before / 2,
                          ok: slope <= before / 2 ? 'ok' : 'MORE')
        end
      end

      # One worker per size (its own process: its peak RSS is its own),
      # asked in turn: warm rounds, peak RSS, cold rounds; then loading and
      # the plan process, in turn again.
      def measure_sizes(apps)
        workers = apps.transform_values { |app_dir| Worker.new(app_dir, eviction_mb: EVICTION_MB) }
        rows = workers.to_h { |n, worker| [n, worker.ask('loaded').merge('devices' => n)] }
        best_of(rounds(workers, cold: false)).each { |n, best| rows[n].merge!(best) }
        workers.each { |n, worker| rows[n]['rss_mb'] = worker.ask('rss') }
        best_of(rounds(workers, cold: true)).each { |n, best| rows[n].merge!(best.transform_keys { |k| "cold #{k}" }) }
        workers.each_value(&:stop)
        processes(apps, rows)
        rows.values
      end

      # The runs of every size, by size.
      def rounds(workers, cold:)
        runs = workers.transform_values { [] }
        ROUNDS.times { workers.each { |n, worker| runs[n].concat(worker.ask('runs', ROUND_SECONDS, cold)) } }
        runs
      end

      # The best of each figure, but for the GC time: its mean (the best is
      # the run that happened to collect nothing).
      def best_of(runs_by_size)
        runs_by_size.transform_values do |runs|
          best = runs.first.keys.to_h { |k| [k, runs.map { |r| r[k] }.min] }
          best.merge('gc' => runs.sum { |r| r['gc'] } / runs.size, 'runs' => runs.size)
        end
      end

      # Loading in fresh processes (the worker's own load is one more) and
      # the whole `syskit plan --format json` and `syskit check` processes
      # (wall and CPU).
      def processes(apps, rows)
        PROCESS_RUNS.times do |i|
          apps.each do |n, app_dir|
            row = rows[n]
            # The worker's own load compiled the app's files (see
            # ISeqCache); these read them back, as every later run does.
            load, objects, generate_objects = load_time(app_dir)
            row['load'] = i.zero? ? load : [row['load'], load].min
            row['load_objects'] = i.zero? ? objects : [row['load_objects'], objects].min
            row['first_generate_objects'] = generate_objects
            { 'process' => %w[plan --format json], 'check' => %w[check] }.each do |key, command|
              wall, cpu = process_time(app_dir, command)
              row[key] = [row[key], wall].compact.min
              row["#{key} cpu"] = [row["#{key} cpu"], cpu].compact.min
            end
          end
        end
      end

      def load_time(app_dir)
        worker = Worker.new(app_dir, eviction_mb: EVICTION_MB)
        worker.ask('loaded').values_at('load', 'load_objects', 'first_generate_objects')
      ensure
        worker&.stop
      end

      # [wall, CPU] seconds of the whole `syskit COMMAND --app APP` process,
      # Ruby start-up included.
      def process_time(app_dir, command)
        before = Process.times
        start = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        ok = system(RbConfig.ruby, BIN, *command, '--app', app_dir, out: File::NULL)
        raise "syskit #{command.first} failed on #{app_dir}" unless ok

        after = Process.times
        [Process.clock_gettime(Process::CLOCK_MONOTONIC) - start,
         (after.cutime - before.cutime) + (after.cstime - before.cstime)]
      end

      COLUMNS = [['devices', 'devices', '%d'], ['tasks', 'tasks', '%d'], %w[runs runs %d], ['load', 'load s', '%.3f'],
                 ['load_objects', 'load objects', '%d']] +
                PHASES.map { |p| [p, p, '%.4f'] } +
                [['generate', 'generate s', '%.3f'], ['gc', 'GC s (mean)', '%.3f'], %w[objects objects %d],
                 ['first_generate_objects', 'first objects', '%d'], ['filters', 'filters s', '%.4f'],
                 ['json', 'json s', '%.3f'],
                 ['text', 'text s', '%.3f'], ['dot', 'dot s', '%.3f'], ['rss_mb', 'peak RSS MB', '%.0f'],
                 ['process', 'plan process s', '%.2f'], ['check', 'check process s', '%.2f']].freeze
      # The figures whose growth is printed, from memory (the CPU caches
      # emptied before each phase) and back to back.
      COLD = (PHASES + %w[filters] + RENDERERS).map { |k| "cold #{k}" }.freeze
      WARM = (%w[load load_objects] + PHASES + ['generate', 'generate without GC', 'objects', 'first_generate_objects',
                                                'filters'] + RENDERERS + %w[process check]).freeze

      def print_table(out, rows)
        cells = rows.map { |r| COLUMNS.map { |key, _, fmt| format(fmt, r.fetch(key)) } }
        widths = COLUMNS.each_with_index.map { |(_, title, _), i| ([title.size] + cells.map { |c| c[i].size }).max }
        out.puts COLUMNS.each_with_index.map { |(_, title, _), i| title.rjust(widths[i]) }.join('  ')
        cells.each { |c| out.puts c.each_with_index.map { |v, i| v.rjust(widths[i]) }.join('  ') }
      end

      # log10(t(10,000) / t(1,000)): 1.0 is linear, 2.0 quadratic.
      # Between consecutive sizes from 1,000 devices up (below that, fixed
      # costs dominate). First with the CPU caches emptied before each
      # phase, so that both sizes start from memory: that is how the
      # algorithm scales. Then back to back, as measured in the table: a
      # 1,000-device network stays in the caches from one run to the next,
      # a 10,000-device one does not, and every memory access shows it.
      # Each says whether it is linear (see Growth; the whole processes
      # start with the same fixed start-up, so they grow less than linearly).
      def print_exponents(out, rows)
        rows.sort_by { |r| r['devices'] }.each_cons(2) do |small, large|
          next if small['devices'] < 1000

          out.puts "scaling exponent #{delimited(small['devices'])} -> #{delimited(large['devices'])} devices " \
                   '(1.0 is linear, 2.0 quadratic)'
          out.puts "  each phase from memory (CPU caches emptied first): #{exponents(small, large, COLD)}"
          out.puts "  back to back: #{exponents(small, large, WARM)}"
        end
      end

      def exponents(small, large, keys)
        found = keys.to_h do |k|
          [k.delete_prefix('cold '), Growth.exponent(small['devices'], small[k], large['devices'], large[k])]
        end
        "#{found.map { |k, e| "#{k} #{format('%.2f', e)}" }.join(', ')}; #{Growth.verdict(found)}"
      end

      def delimited(number)
        number.to_s.reverse.scan(/\d{1,3}/).join(',').reverse
      end
    end
  end
end

if $PROGRAM_NAME == __FILE__
  parts = Syskit::Bench.parts(ENV['ONLY'] || ENV.fetch('SYSKIT_BENCH_ONLY', nil))
  # Whole processes are timed as users start them, without Bundler: under
  # `bundle exec rake bench` each would inherit its RUBYOPT (-rbundler/setup)
  # and load Bundler first (0.15 s more for every one, ruby -e 1 included).
  ENV.replace(Bundler.unbundled_env) if defined?(Bundler)
  # The compiled code of the gem and of the bench apps (see ISeqCache), in
  # a cache of this run's own: the apps are thrown away at the end.
  Dir.mktmpdir('syskit-bench-cache') do |cache|
    ENV['SYSKIT_CACHE_DIR'] = cache
    Syskit::ISeqCache.install
    puts "machine: #{Syskit::Bench::Startup.machine}"
    parts.each_value do |part|
      part.call
      puts
    end
  end
  puts "load average at the end: #{Syskit::Bench::Startup.load_average}"
end
