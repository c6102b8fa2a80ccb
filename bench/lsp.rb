# frozen_string_literal: true

# How long `syskit lsp` takes to publish the diagnostics of a change, seen
# from the editor (from the didChange sent to the diagnostics read), on a
# synthetic app of 100 devices with compositions (bench/synthetic_app.rb):
# a profile edited (the app loaded and checked again) and a configuration
# file edited (that file read again, the profiles generated again), each
# change making a mistake then fixing it. Run as `ruby -Ilib bench/lsp.rb`;
# SYSKIT_BENCH_LSP_DEVICES sets the sizes. Figures are measured on each
# run, never stored.

require 'syskit'
require 'tmpdir'
require_relative 'synthetic_app'
require_relative '../test/lsp/lsp_client'

module Syskit
  module Bench
    # The language server benchmark.
    module LSP
      SIZES = ENV.fetch('SYSKIT_BENCH_LSP_DEVICES', '100').split(',').map { |s| Integer(s) }
      RUNS = 10
      # "Well under a second" (issue 41).
      TARGET = 0.5

      module_function

      def run(io = $stdout)
        io.puts "syskit lsp: from a change sent to its diagnostics read (median and best of #{RUNS} changes; " \
                "load average #{File.read('/proc/loadavg').split.first if File.file?('/proc/loadavg')})"
        io.puts '  devices  edited          wall s, median/best  server CPU s, median'
        SIZES.each do |devices|
          results = Dir.mktmpdir('syskit-bench-lsp') { |dir| measure(File.join(dir, 'app'), devices) }
          results.zip(%w[profile configuration]).each do |(wall, cpu), what|
            io.puts format('  %<n>7d  %<what>-13s  %<wm>8.3f / %<wb>.3f  %<cpu>20.3f  %<ok>s',
                           n: devices, what: what, wm: median(wall), wb: wall.min, cpu: median(cpu),
                           ok: median(wall) < TARGET ? 'ok' : "SLOWER than #{TARGET} s")
          end
        end
      end

      def measure(root, devices)
        SyntheticApp.write(root, devices, compositions: true)
        client = SelfTest::LSPClient.new(env: ENV.to_h, chdir: root)
        client.request('initialize', processId: Process.pid, rootUri: Syskit::LSP::URI.of(root), capabilities: {})
        profile = File.join(root, 'models', 'profiles', 'base.rb')
        conf = File.join(root, 'config', 'orogen', 'bench::MotorTask.yml')
        [[profile, ->(t) { t.sub("with_conf('default', 's2')", "with_conf('default', 'nope')") }],
         [conf, ->(t) { t.sub('gain: 1.0', 'gai: 1.0') }]].map do |path, mistake|
          times(client, path, mistake)
        end
      ensure
        client&.close
      end

      # The wall and server CPU times of each change, alternately the
      # mistake and its fix: [[wall, ...], [cpu, ...]].
      def times(client, path, mistake)
        text = File.read(path)
        client.open(path, text)
        client.diagnostics_of(path)
        (1..RUNS).map do |version|
          started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
          cpu = cpu_time(client.pid)
          client.change(path, version.odd? ? mistake.call(text) : text, version: version + 1)
          diagnostics = client.diagnostics_of(path)
          raise "no diagnostic for the mistake in #{path}" if version.odd? && diagnostics.empty?

          [Process.clock_gettime(Process::CLOCK_MONOTONIC) - started, cpu_time(client.pid) - cpu]
        end.transpose
      end

      # The CPU time of process +pid+ so far (Linux's /proc, in clock ticks
      # of 1/100 s); 0 elsewhere.
      def cpu_time(pid)
        stat = "/proc/#{pid}/stat"
        return 0.0 unless File.file?(stat)

        File.read(stat).split(') ').last.split.values_at(11, 12).sum { |t| Integer(t) } / 100.0
      end

      def median(values)
        values.sort[values.size / 2]
      end
    end
  end
end

Syskit::Bench::LSP.run if $PROGRAM_NAME == __FILE__
