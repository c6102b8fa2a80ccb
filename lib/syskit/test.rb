# frozen_string_literal: true

require 'minitest/autorun'
require 'minitest/spec'
require 'syskit'
require 'syskit/test/stubs'
require 'syskit/test/profile_assertions'
require 'syskit/test/task_assertions'
require 'syskit/test/runtime_only'
require 'syskit/test/model_helpers'
require 'syskit/test/subject_model'
require 'syskit/test/app_under_test'
require 'syskit/test/load_problems'
require 'syskit/test/checked_nothing'

module Syskit
  # Test support for apps: `require 'syskit/test'` at the top of a test
  # file loads the app containing the current directory (once per run),
  # and every `describe` block gets the stubs and profile assertions:
  #
  #   describe OroGen.roboteq.Task do
  #     it 'configures its filter' do
  #       bus = syskit_stub_com_bus(CommonModels::Devices::Bus::CAN)
  #       dev = syskit_stub_attached_device(bus).can_id(10, 20)
  #       task = syskit_stub_deploy_and_configure(dev)
  #       assert_equal 10, task.properties.can_id
  #     end
  #   end
  module Test
    # The base class of `describe` blocks in app tests.
    class Spec < Minitest::Spec
      include Stubs
      include ProfileAssertions
      include TaskAssertions
      include ModelHelpers
      include RuntimeOnly
      include RuntimeOnly::Mocks
      include SubjectModel
      include LoadProblems::Guard
      extend RuntimeOnly::ClassMethods
      extend SubjectModel::ClassMethods

      # The task returned by the last syskit_stub_deploy_and_configure (or
      # syskit_stub_and_deploy). Not in Syskit's own harness, whose tests
      # name their tasks with +let(:task)+.
      attr_reader :task

      # What Ruby shows of a test in a NameError's message: its name, not
      # every stub and plan it holds.
      def inspect
        "#<#{self.class.name} #{name}>"
      end
    end

    # Syskit's test base classes, for tests written as classes
    # (+class TestX < Syskit::Test::ComponentTest+).
    %i[ComponentTest TaskContextTest RubyTaskContextTest ProfileTest ActionInterfaceTest].each do |name|
      const_set(name, Class.new(Spec))
    end

    # Failures are reported at the test's line: frames of minitest and of
    # this gem are left out of their backtraces.
    class BacktraceFilter < Minitest::BacktraceFilter
      def filter(backtrace)
        kept = super.reject { |line| line.start_with?(Location::GEM_LIB) }
        kept.empty? ? super : kept
      end
    end

    # A test that calls +exit+ (or +abort+) would end the whole run before
    # minitest reports: the failures found so far would be lost, whatever
    # the exit status. It fails instead, at the line that exits.
    module ExitIsAFailure
      def capture_exceptions
        super do
          yield
        rescue SystemExit => e
          what = e.message == 'exit' ? "exit (status #{e.status})" : "abort (#{e.message})"
          failure = Minitest::Assertion.new("the test calls #{what}, which would end the run and hide the report " \
                                            'of every test: use assertions, skip or return instead')
          failure.set_backtrace(e.backtrace)
          raise failure
        end
      end
    end
  end
end

Syskit::Test.app
Minitest::Spec.register_spec_type(Syskit::Test::Spec) { |_desc| true }
Minitest.backtrace_filter = Syskit::Test::BacktraceFilter.new
Minitest::Test.prepend(Syskit::Test::ExitIsAFailure)
