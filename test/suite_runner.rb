# frozen_string_literal: true

require 'minitest'

module Syskit
  module SelfTest
    # How the suite shares out the machine's cores.
    #
    # Tests that only run syskit (or rake, gem, chromium) in processes of
    # their own declare `parallelize_me!`: minitest's threads run them,
    # waiting on those processes.
    #
    # The other tests load apps in the test process, whose globals allow
    # one at a time. They run in two processes: this one and a fork of it,
    # made before any test runs. Each takes the next test class from a
    # shared queue until none is left, and the fork sends its results back
    # to this process's reporter: the run has one summary.
    #
    # SYSKIT_TEST_FORK=0 runs them all in this process.
    module SuiteRunner
      def self.install
        Minitest.singleton_class.prepend(self)
        Minitest::Runnable.singleton_class.prepend(LockedRecords)
      end

      def self.fork?
        ENV['SYSKIT_TEST_FORK'] != '0' && Process.respond_to?(:fork)
      end

      def __run(reporter, options)
        parallel, serial = Minitest::Runnable.runnables.shuffle.partition { |s| s.test_order == :parallel }
        parallel, serial = [parallel, serial].map { |suites| suites.partition { |suite| suite.is_a?(Long) }.flatten }
        queue = ClassQueue.new(serial)
        fork_lane = ForkLane.start(queue, options, reporter) if SuiteRunner.fork?
        parallel.each { |suite| suite.run(reporter, options) }
        queue.each { |suite| suite.run(reporter, options) }
        fork_lane&.finish
      end
    end

    # With tests in threads and in the fork, every test records its result
    # under the reporter's lock (minitest's parallel tests do).
    module LockedRecords
      def run_one_method(klass, method_name, reporter)
        reporter.synchronize { reporter.prerecord(klass, method_name) }
        result = Minitest.run_one_method(klass, method_name)
        reporter.synchronize { reporter.record(result) }
      end
    end

    # A test class that takes long (a fuzz campaign, a browser, a gem
    # installation, the corpus of broken apps) says so with
    # `extend SelfTest::Long`: it is queued first, so that the run does not
    # end waiting on it alone.
    module Long; end

    # Test classes shared by processes: their indices in a pipe, which each
    # process reads one at a time (a read of 4 bytes is never split).
    class ClassQueue
      def initialize(classes)
        @classes = classes
        @reader, writer = IO.pipe
        writer.syswrite(classes.each_index.to_a.pack('N*'))
        writer.close
      end

      def each
        while (index = next_index)
          yield @classes[index]
        end
      end

      private

      def next_index
        @reader.sysread(4).unpack1('N')
      rescue EOFError
        nil
      end
    end

    # The forked process: it runs test classes from the queue and writes
    # each result to a pipe; a thread here records them.
    class ForkLane
      # What the fork sends of a result: Minitest::Result's fields.
      FIELDS = %i[klass name failures assertions time source_location].freeze

      def self.start(queue, options, reporter)
        [$stdout, $stderr].each(&:flush)
        reader, writer = IO.pipe
        pid = fork do
          reader.close
          run(queue, options, writer)
        end
        writer.close
        new(pid, reader, reporter)
      end

      # In the fork: the after_run blocks registered by its own tests run
      # there too (the others are this process's to run), then it leaves
      # without this process's at_exit handlers.
      def self.run(queue, options, writer)
        hooks = Minitest.class_variable_get(:@@after_run).size
        sender = Sender.new(writer)
        queue.each { |suite| suite.run(sender, options) }
        Minitest.class_variable_get(:@@after_run).drop(hooks).reverse_each(&:call)
        writer.close
        [$stdout, $stderr].each(&:flush)
        exit!(0)
      rescue Exception => e # rubocop:disable Lint/RescueException
        warn "the forked test process stopped: #{e.class}: #{e.message}\n  #{e.backtrace.first(5).join("\n  ")}"
        exit!(1)
      end

      # The results are recorded as they come: the fork would wait on a
      # full pipe.
      def initialize(pid, reader, reporter)
        @pid = pid
        @recorder = Thread.new do
          while (fields = next_fields(reader))
            result = Minitest::Result.new(fields[1])
            FIELDS.zip(fields).each { |field, value| result.public_send("#{field}=", value) }
            reporter.synchronize { reporter.record(result) }
          end
        end
      end

      def finish
        @recorder.join
        _, status = Process.wait2(@pid)
        raise "the forked test process failed (#{status}): see its message above" unless status.success?
      end

      private

      def next_fields(reader)
        Marshal.load(reader) # rubocop:disable Security/MarshalLoad -- from our own fork
      rescue EOFError
        nil
      end

      # The reporter of the fork.
      class Sender
        def initialize(writer)
          @writer = writer
        end

        def synchronize
          yield
        end

        def prerecord(_klass, _name); end

        def record(result)
          fields = FIELDS.map { |field| result.public_send(field) }
          fields[2] = fields[2].map { |failure| portable(failure) }
          Marshal.dump(fields, @writer)
        end

        # An unexpected error that Marshal cannot write is sent as a
        # RuntimeError saying what it was.
        def portable(failure)
          Marshal.dump(failure)
          failure
        rescue ::TypeError
          error = RuntimeError.new("#{failure.error.class}: #{failure.error.message}")
          error.set_backtrace(failure.error.backtrace)
          Minitest::UnexpectedError.new(error)
        end
      end
    end
  end
end
