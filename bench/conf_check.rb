# frozen_string_literal: true

# Measures `syskit check` on a configuration file whose section sets N
# properties the task does not have (each one a located error), as whole
# processes, from 2,000 to 200,000 properties, and the exponent fitted to
# the times (least squares on log-log: 1.0 is linear, 2.0 quadratic). Run
# as `ruby -Ilib bench/conf_check.rb`; bench/run.rb calls
# Syskit::Bench::ConfCheck.run. Figures are measured on each run, never
# stored.

require 'fileutils'
require 'open3'
require 'rbconfig'
require 'tmpdir'
require_relative 'growth'

module Syskit
  module Bench
    # The configuration check benchmark: a synthetic app per size.
    module ConfCheck
      SIZES = (ENV['SYSKIT_BENCH_CONF_SIZES'] || '2000,20000,200000').split(',').map { |s| Integer(s) }
      # The whole process on the largest file, in seconds.
      TARGET = 5.0
      RUNS = 3
      BIN = File.expand_path('../bin/syskit', __dir__)

      module_function

      def run(io = $stdout)
        times = Dir.mktmpdir('syskit-bench') do |dir|
          SIZES.to_h { |n| [n, process_time(write_app(File.join(dir, "conf#{n}"), n))] }
        end
        io.puts "syskit check on a configuration file of N unknown properties, whole process (best of #{RUNS})"
        io.puts '  properties  file MB  check s'
        times.each do |n, (s, bytes)|
          io.puts format('  %<n>10d  %<mb>7.1f  %<s>7.2f', n: n, mb: bytes / 1e6, s: s)
        end
        fitted = exponent(times)
        io.puts "  fitted scaling exponent (1.0 is linear, 2.0 quadratic): #{format('%.2f', fitted)}; " \
                "#{Growth.verdict('fitted' => fitted)}"
        largest, (seconds, _bytes) = times.max_by(&:first)
        io.puts format('  %<n>d properties: %<s>.2f s, target %<t>.1f s  %<ok>s',
                       n: largest, s: seconds, t: TARGET, ok: seconds < TARGET ? 'ok' : 'SLOW')
        times
      end

      # The slope of log(time) against log(size), by least squares.
      def exponent(times)
        points = times.map { |n, (s, _bytes)| [Math.log(n), Math.log(s)] }
        mean_x = points.sum(&:first) / points.size
        mean_y = points.sum(&:last) / points.size
        points.sum { |x, y| (x - mean_x) * (y - mean_y) } / points.sum { |x, _| (x - mean_x)**2 }
      end

      # An app with one task library and a configuration file of +count+
      # properties its task does not have; returns [root, file size].
      def write_app(dir, count)
        file(dir, 'config/syskit.yml', "name: Bench\n")
        file(dir, 'config/robots/default.rb', "# nothing deployed\n")
        file(dir, 'models/orogen/imu.orogen',
             "name 'imu'\ntask_context 'Task' do\n  property 'rate', 'int', 100\nend\n")
        bytes = file(dir, 'config/orogen/imu::Task.yml',
                     "--- name:default\n#{Array.new(count) { |i| "unknown_property_#{i}: #{i}\n" }.join}")
        [dir, bytes]
      end

      def file(dir, path, content)
        FileUtils.mkdir_p(File.dirname(File.join(dir, path)))
        File.write(File.join(dir, path), content)
      end

      # The best of RUNS whole `syskit check` processes on +app+, and the
      # size of its file.
      def process_time((app, bytes))
        best = Array.new(RUNS) do
          start = Process.clock_gettime(Process::CLOCK_MONOTONIC)
          out, err, status = Open3.capture3(RbConfig.ruby, BIN, 'check', '--app', app)
          # Exit status 1: the unknown properties are errors, as they must be.
          raise "syskit check failed on #{app}: #{err}#{out.lines.last(3).join}" unless status.exitstatus == 1

          Process.clock_gettime(Process::CLOCK_MONOTONIC) - start
        end.min
        [best, bytes]
      end
    end
  end
end

Syskit::Bench::ConfCheck.run if $PROGRAM_NAME == __FILE__
