# frozen_string_literal: true

module Syskit
  module Test
    # What a problem met while loading the app or a test file means for the
    # run, as in Roby, where a load error ends it: the run fails whatever
    # its tests say (and whatever -n selects), and a test whose subject (the
    # model or profile of its +describe+) did not load, itself or through a
    # file it requires, errors at the load error's file:line instead of
    # passing on what little was defined.
    module LoadProblems
      # The error of a test whose subject did not load.
      class SubjectNotLoaded < StandardError; end

      class << self
        # The reports of the test files that did not load.
        def test_files
          @test_files ||= []
        end

        # How many problems stopped part of the app or of its tests loading.
        def total
          Test.app.errors.size + test_files.size
        end

        # Raises SubjectNotLoaded when the file declaring +subject+ failed
        # to load (a file it requires failing makes it fail too).
        def check_subject(app, subject)
          location = subject.declared_at if subject.respond_to?(:declared_at)
          failure = location && app.file_load_failure(location.path)
          return unless failure

          error = SubjectNotLoaded.new(subject_message(app, subject, failure))
          error.set_backtrace(["#{failure.path}:#{failure.lineno}"])
          raise error
        end

        private

        def subject_message(app, subject, failure)
          problem = app.errors.find { |e| e.location == failure }
          cause = problem ? problem.report(Dir.pwd) : failure.to_s(Dir.pwd)
          "#{subject.name} did not load completely, so this test cannot check it:\n#{cause}"
        end
      end

      # The +describe+ blocks' hook: each test first checks its subjects.
      module Guard
        def before_setup
          super
          self.class.ancestors.each do |klass|
            break if klass == Spec

            LoadProblems.check_subject(Test.app, LoadProblems.subject_of(klass))
          end
        end
      end

      # The model or profile a +describe+ block is about, if any.
      def self.subject_of(klass)
        desc = klass.desc if klass.respond_to?(:desc)
        return desc.syskit_profile if desc.respond_to?(:syskit_profile)

        desc if desc.is_a?(Actions::Profile) || (desc.is_a?(Class) && desc < AbstractComponent)
      end

      # A minitest reporter that fails the run when anything failed to load.
      class Reporter < Minitest::AbstractReporter
        def initialize(io)
          super()
          @io = io
        end

        def passed?
          LoadProblems.total.zero?
        end

        def report
          return if passed?

          count = LoadProblems.total
          @io.puts "\n#{count} problem(s) loading the app or its test files (printed before the tests): " \
                   'the run fails whatever its tests say; fix them first'
        end
      end
    end
  end
end

# minitest's plugin interface: Minitest.run calls plugin_NAME_init for each
# name in Minitest.extensions.
Minitest.define_singleton_method(:plugin_syskit_load_problems_init) do |options|
  reporter << Syskit::Test::LoadProblems::Reporter.new(options[:io])
end
Minitest.extensions << 'syskit_load_problems' unless Minitest.extensions.include?('syskit_load_problems')
