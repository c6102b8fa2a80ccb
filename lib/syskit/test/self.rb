# frozen_string_literal: true

require 'minitest/autorun'
require 'minitest/spec'
require 'tmpdir'
require 'pp' # Syskit's tests pretty-print models (PP.pp), its harness loads it
require 'syskit'
require 'syskit/test/app_under_test'
require 'syskit/test/self_app'
require 'syskit/test/plan'
require 'syskit/test/stubs'
require 'syskit/test/stub_network'
require 'syskit/test/profile_assertions'
require 'syskit/test/runtime_only'
require 'syskit/test/model_helpers'
require 'syskit/test/network_manipulation'
require 'syskit/test/conformance_report'
require 'syskit/test/unmodelled_classes'

begin
  require 'flexmock/minitest'
rescue LoadError
  abort 'syskit/test/self: Syskit\'s tests use flexmock; add it to your Gemfile (gem "flexmock") and run bundle install'
end

module Syskit
  module Test
    # The harness of Syskit's own test suite (+require "syskit/test/self"+
    # at the top of each of rock-core/tools-syskit's test files), without
    # an app: every test gets a fresh robot (+robot+), a plan holding task
    # instances as data (+plan+), and the models and constants it defined
    # are removed after it, as Syskit's harness does.
    #
    # What needs a running system (Roby's execution engine, Orocos
    # components) skips at its call, saying so: see RuntimeOnly.
    module Self
      include Stubs
      include ProfileAssertions
      include ModelHelpers
      include RuntimeOnly
      include NetworkManipulation
      include RuntimeOnly::OfSyskit

      # The robot of the test (Syskit::Robot::RobotDefinition), made anew
      # for each test.
      attr_reader :robot

      def before_setup
        @robot = Robot::RobotDefinition.new
        @plan = Plan.new
        super
      end

      # The plan of the test: task instances added as data.
      attr_reader :plan

      # The models the test defined are removed, and the constants naming
      # them, as Syskit's harness does.
      def after_teardown
        super
        clear_newly_defined_models
      end

      # The app the tests run in: empty, made once per process (see SelfApp).
      def app
        SelfApp.app
      end

      # +data_service_type 'Name' do ... end+: a data service model of
      # that name, as Syskit's harness makes them.
      def data_service_type(name, &)
        DataService.new_submodel(name: name, &)
      end

      # Asserts that +result+ is the placeholder model standing for
      # +models+ (data service models, a component model, bound services).
      def assert_is_proxy_model_for(models, result)
        service = nil
        proxied = Array(models).map do |model|
          next model unless model.is_a?(Models::BoundDataService)

          service = model
          model.component_model
        end
        expected = Models::Placeholder.for(proxied)
        expected = service.attach(expected) if service
        assert_equal expected, result, "#{result} was expected to be a proxy model for #{models} (#{expected})"
      end
    end
  end
end

Syskit::Test::SelfApp.app
Syskit::Test::UnmodelledClasses.define_all
Minitest::Test.include(Syskit::Test::Self)
Minitest::Test.extend(Syskit::Test::RuntimeOnly::ClassMethods)
