# frozen_string_literal: true

require 'etc'
require 'rbconfig'

module Syskit
  module Bench
    # Start-up: `syskit --version`, `syskit help`, and `syskit plan` and
    # `syskit check` of the example app, beside `ruby -e 1`, whole
    # processes (no Bundler, the compiled-code cache warm after the first
    # run, see ISeqCache), interleaved, best of RUNS, wall and CPU. Run
    # as `ruby bench/startup.rb`; bench/run.rb calls it first.
    module Startup
      RUNS = Integer(ENV.fetch('SYSKIT_BENCH_STARTUP_RUNS', '20'))
      # How much longer than `ruby -e 1` each may take, in seconds: the
      # everyday commands on the example app (issue 40) have more to do.
      TARGETS = { 'syskit --version' => 0.05, 'syskit help' => 0.05, 'syskit plan' => 0.08,
                  'syskit check' => 0.08 }.freeze
      BIN = File.expand_path('../bin/syskit', __dir__)
      EXAMPLE = File.expand_path('../examples/awesome_robot', __dir__)
      COMMANDS = { 'ruby -e 1' => ['-e', '1'], 'syskit --version' => [BIN, '--version'],
                   'syskit help' => [BIN, 'help'], 'syskit plan' => [BIN, 'plan', '--app', EXAMPLE],
                   'syskit check' => [BIN, 'check', '--app', EXAMPLE] }.freeze

      module_function

      def run(out = $stdout)
        times = COMMANDS.transform_values { [] }
        RUNS.times { COMMANDS.each { |name, args| times[name] << process_time(args) } }
        best = times.transform_values { |runs| [runs.map(&:first).min, runs.map(&:last).min] }
        ruby = best.fetch('ruby -e 1')
        out.puts "Start-up, whole processes without Bundler (best of #{RUNS} interleaved runs)"
        out.puts '  command              wall s   CPU s   beyond ruby -e 1   target'
        best.each do |name, (wall, cpu)|
          extra = wall - ruby.first
          limit = TARGETS[name]
          target = extra <= limit.to_f ? "<= #{limit}  ok" : "> #{limit}  SLOW"
          verdict = name == 'ruby -e 1' ? '' : format('%<extra>+.3f s %<target>12s', extra: extra, target: target)
          out.puts format('  %-18<name>s %7.3<wall>f %7.3<cpu>f   %<verdict>s', name: name, wall: wall, cpu: cpu,
                                                                                verdict: verdict).rstrip
        end
        best
      end

      # [wall, CPU] seconds of `ruby ARGS`.
      def process_time(args)
        before = Process.times
        start = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        system(RbConfig.ruby, *args, out: File::NULL, err: File::NULL) or raise "ruby #{args.join(' ')} failed"
        after = Process.times
        [Process.clock_gettime(Process::CLOCK_MONOTONIC) - start,
         (after.cutime - before.cutime) + (after.cstime - before.cstime)]
      end

      # The machine, for the record.
      def machine
        cpu = File.read('/proc/cpuinfo')[/^model name\s*:\s*(.+)$/, 1] if File.readable?('/proc/cpuinfo')
        "#{cpu || RbConfig::CONFIG['host_cpu']}, #{Etc.nprocessors} cores, #{RUBY_DESCRIPTION}; " \
          "load average #{load_average}"
      end

      def load_average
        File.readable?('/proc/loadavg') ? File.read('/proc/loadavg').split.first(3).join(' ') : 'unknown'
      end
    end
  end
end

Syskit::Bench::Startup.run if $PROGRAM_NAME == __FILE__
