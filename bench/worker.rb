# frozen_string_literal: true

require 'json'
require 'syskit'
require 'syskit/check'
require 'syskit/render/json'
require 'syskit/render/text'
require 'syskit/render/dot'

module Syskit
  module Bench
    # A child process that loads one synthetic app, then measures
    # generation and rendering on it each time the parent asks. The parent
    # asks each size's worker in turn, round after round, so that a slow
    # moment of a shared machine falls on every size alike rather than on
    # the one that happened to run then.
    class Worker
      PHASES = %w[instantiate merge buses deploy order configure connect plan].freeze
      RENDERERS = { 'json' => Render::JSON, 'text' => Render::Text, 'dot' => Render::Dot }.freeze

      # Forks the worker; it loads +app_dir+ right away.
      def initialize(app_dir, eviction_mb:)
        commands, @commands = IO.pipe
        @answers, answers = IO.pipe
        @pid = fork do
          @commands.close
          @answers.close
          Runner.new(app_dir, eviction_mb).serve(commands, answers)
        end
        commands.close
        answers.close
      end

      # Sends a command ('loaded', 'runs', 'rss'; see Runner) and returns
      # the worker's answer.
      def ask(*command)
        @commands.puts(JSON.generate(command))
        answer = @answers.gets
        raise "the benchmark worker #{@pid} stopped (#{Process.wait2(@pid).last})" unless answer

        JSON.parse(answer)
      end

      # Workers forked later hold this worker's pipes too, so it is told to
      # stop rather than left to see them close.
      def stop
        @commands.puts(JSON.generate(['stop']))
        @commands.close
        @answers.close
        Process.wait(@pid)
      end

      # The worker's side: one loaded app and its measurements.
      class Runner
        def initialize(app_dir, eviction_mb)
          @app = App.new(app_dir)
          @loaded = measure { @app.load!(robots: ['default']) }
          @profile = @app.profiles.values.first
          # The first generation of the process, as `syskit plan` runs it
          # (later runs find the models' caches filled).
          @first = measure(nil, gc_first: false) { Network::Generator.plan_profile(@app, @profile) }
          @eviction_mb = eviction_mb
        end

        def serve(commands, answers)
          while (line = commands.gets)
            command, *args = JSON.parse(line)
            break if command == 'stop'

            answers.puts(JSON.generate(public_send(command, *args)))
            answers.flush
          end
          exit!(0)
        end

        # How long loading took, and the objects it and the first
        # generation allocated.
        def loaded
          { 'load' => @loaded[0], 'load_objects' => @loaded[1], 'first_generate_objects' => @first[1] }
        end

        # Generation and rendering, at least once and for at least +seconds+.
        # +cold+: with the CPU caches emptied before each phase, so that a
        # small network starts from memory as a large one does.
        def runs(seconds, cold)
          empty_caches = cold ? method(:empty_caches) : nil
          started = now
          done = [one_run(empty_caches)]
          done << one_run(empty_caches) while now - started < seconds
          done
        end

        # Peak resident memory so far, in MB.
        def rss
          File.read('/proc/self/status')[/^VmHWM:\s+(\d+) kB/, 1].to_i / 1024.0
        end

        private

        def one_run(empty_caches)
          result = nil
          time, objects, gc = measure do
            result = Network::Generator.plan_profile(@app, @profile, before_step: empty_caches)
          end
          run = { 'generate' => time, 'gc' => gc, 'generate without GC' => time - gc, 'objects' => objects,
                  'tasks' => result.plan.tasks.size }
          run.merge!(result.timings.slice(*PHASES))
          # syskit check's CAN filter-overlap check, on every bus.
          run['filters'], = measure(empty_caches) { Checks::CanFilters.new(@profile.robot).warnings }
          # Rendering as `syskit plan` does it: written to an IO (here the
          # null device, so the disk is not measured).
          File.open(File::NULL, 'w') do |null|
            RENDERERS.each do |name, renderer|
              run[name], = measure(empty_caches) { renderer.write(result.plan, null) }
            end
          end
          run
        end

        # Reads a buffer larger than the CPU's last-level cache.
        def empty_caches
          @eviction ||= "\1" * (@eviction_mb << 20)
          @eviction.sum
        end

        # Seconds, allocated objects, and seconds of garbage collection
        # (counted by Ruby in whole milliseconds); after a full collection
        # unless +gc_first+ is false.
        def measure(before = nil, gc_first: true)
          GC.start if gc_first
          before&.call
          objects = GC.stat(:total_allocated_objects)
          gc = GC.stat(:time)
          start = now
          yield
          [now - start, GC.stat(:total_allocated_objects) - objects, (GC.stat(:time) - gc) / 1000.0]
        end

        def now
          Process.clock_gettime(Process::CLOCK_MONOTONIC)
        end
      end
    end
  end
end
