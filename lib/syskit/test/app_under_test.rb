# frozen_string_literal: true

module Syskit
  # Test support: see syskit/test (apps' tests) and syskit/test/self
  # (Syskit's own tests).
  module Test
    class << self
      # The app under test: SYSKIT_APP, else the app containing the current
      # directory. Loaded once, with every task library of the app.
      def app
        @app ||= load_app
      end

      # The harness of Syskit's own tests sets its own, empty, app.
      attr_writer :app

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
      # often the cause of what fails next), are one failing test of their
      # own, and fail the run whatever -n selects (see LoadProblems).
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
