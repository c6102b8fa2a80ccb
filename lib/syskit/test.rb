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
      include SubjectModel
      extend RuntimeOnly::ClassMethods
      extend SubjectModel::ClassMethods
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

    class << self
      # The app under test: SYSKIT_APP, else the app containing the current
      # directory. Loaded once, with every task library of the app.
      def app
        @app ||= load_app
      end

      # The robot configuration deployments come from: SYSKIT_ROBOT or 'default'.
      def robot
        ENV.fetch('SYSKIT_ROBOT', 'default')
      end

      private

      def load_app
        root = ENV['SYSKIT_APP'] || App.find_root(Dir.pwd)
        unless root
          abort "syskit/test: #{Dir.pwd} is not in a Syskit app (no models/ directory above it); set SYSKIT_APP"
        end

        app = App.new(root)
        auto_load = App::InitFile.auto_load_models?(root)
        app.load(robots: [robot], everything: auto_load, models: auto_load)
        report_load_problems(app) unless app.errors.empty?
        app
      end

      # An app with problems still runs its tests (a bundle may hold files
      # Rock itself never loads, and the tests that do not use them say so
      # by passing); the problems are printed first, on stderr (they are
      # often the cause of what fails next), and are one failing test of
      # their own.
      def report_load_problems(app)
        app.errors.each { |problem| warn problem.report(Dir.pwd) }
        report = app.errors.map { |e| e.report(app.root) }.join("\n")
        count = app.errors.size
        Class.new(Minitest::Test) do
          define_singleton_method(:name) { "#{app.name} (loading)" }
          define_method(:test_the_app_loads_without_problems) do
            flunk "#{app.name} has #{count} problem(s); the tests that use these files fail too:\n#{report}"
          end
        end
      end
    end
  end
end

Syskit::Test.app
Minitest::Spec.register_spec_type(Syskit::Test::Spec) { |_desc| true }
Minitest.backtrace_filter = Syskit::Test::BacktraceFilter.new
Minitest::Test.prepend(Syskit::Test::ExitIsAFailure)
