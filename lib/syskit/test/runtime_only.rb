# frozen_string_literal: true

require 'syskit/test/plan'

module Syskit
  module Test
    # What Syskit's tests do with a running system (Roby's plan and
    # execution engine, Orocos components): each of these skips the test it
    # is called in, saying why, so that such a test is never an error and
    # never a pass.
    module RuntimeOnly
      REASON = "needs Syskit's runtime (Roby and Orocos)"

      # Test methods of Syskit's harness that need a running system.
      METHODS = %i[
        syskit_deploy syskit_deploy_and_configure syskit_configure syskit_start syskit_configure_and_start
        syskit_deploy_configure_and_start syskit_stub_deploy_configure_and_start
        syskit_start_execution_agents syskit_write syskit_create_reader syskit_create_writer syskit_stop
        syskit_stub_deployment expect_execution execute execute_one_cycle plan assert_event_emission
        assert_has_one_new_sample assert_has_no_new_sample assert_event_command_failed assert_times_out
        assert_fatal_exception assert_transitions_to_state execute_robot_controller
        expect_execution_default_timeout= use_deployment use_ruby_tasks use_unmanaged_task
        execution_engine droby_remote_marshaller droby_dump droby_marshalled_and_unmarshalled
        assert_droby_compatible create_transaction
        syskit_run_planner_with_full_deployment run_planners deploy_current_plan
      ].freeze

      METHODS.each do |name|
        define_method(name) { |*_args, **_options, &_block| skip("#{name} #{REASON}") }
      end

      # Roby's +capture_log(object, level) { ... }+: the messages +object+
      # logs at +level+ while the block runs. The block runs; models log
      # nothing through Roby's loggers here, so none are captured.
      def capture_log(_object, _level)
        yield
        []
      end

      # Helpers that configure tasks: in an app's tests (syskit/test) they
      # check the configuration of the models (see TaskAssertions); in
      # Syskit's own tests (syskit/test/self) they configure Orocos
      # components, and skip.
      module OfSyskit
        METHODS = %i[syskit_stub_deploy_and_configure syskit_stub_requirements_and_configure].freeze

        METHODS.each do |name|
          define_method(name) { |*_args, **_options, &_block| skip("#{name} #{REASON}") }
        end
      end

      # Methods of Roby's plan that need it running (the plan of Syskit's
      # harness holds tasks as data, see Test::Plan), or its relation
      # graphs, which Roby's engine keeps: each skips.
      PLAN_METHODS = %i[execution_engine in_transaction task_relation_graph_for].freeze

      PLAN_METHODS.each do |name|
        Plan.define_method(name) { |*_args, **_options, &_block| raise Minitest::Skip, "plan.#{name} #{REASON}" }
      end

      # Methods of Syskit's components that need them running (setting up,
      # Roby's explicit fullfilled model of a task being planned): each
      # skips.
      COMPONENT_METHODS = %i[ready_for_setup? setup fullfilled_model=].freeze

      COMPONENT_METHODS.each do |name|
        next if Component.method_defined?(name)

        Component.define_method(name) { |*_args, **_options, &_block| raise Minitest::Skip, "task.#{name} #{REASON}" }
      end

      # Methods of a task's ports that read or write its data: each skips.
      PORT_METHODS = %i[reader writer].freeze

      PORT_METHODS.each do |name|
        next if Port.method_defined?(name)

        Port.define_method(name) { |*_args, **_options, &_block| raise Minitest::Skip, "port.#{name} #{REASON}" }
      end

      # Methods of Syskit's tasks about a running component (whether it is
      # configured, must be reconfigured, may be reused, the property
      # values written to it): each skips.
      TASK_METHODS = %i[can_be_deployed_by? reusable? needs_reconfiguration? property_overrides
                        clear_property_overrides].freeze

      TASK_METHODS.each do |name|
        TaskContext.define_method(name) { |*_args, **_options, &_block| raise Minitest::Skip, "task.#{name} #{REASON}" }
      end

      # Test helpers of Syskit about what this gem does not model (Roby's
      # plans): the test is skipped, saying so.
      NOT_MODELLED_HELPERS = %i[syskit_stub_requirements syskit_generate_network].freeze
      NOT_MODELLED = 'is about what this gem does not model (Roby): skipped'

      NOT_MODELLED_HELPERS.each do |name|
        define_method(name) { |*_args, **_options, &_block| skip("#{name} #{NOT_MODELLED}") }
      end

      # The tests of a Roby task or an action interface are skipped: these
      # are not modelled.
      # Nested describe blocks count: their classes are subclasses of the
      # outer ones.
      def before_setup
        super
        described = self.class.ancestors.grep(Class).filter_map { |k| k.desc if k.respond_to?(:desc) }
        model = described.find { |desc| desc.is_a?(Module) && desc.singleton_class.include?(Compat::NotModelledModel) }
        skip("#{model} #{NOT_MODELLED}") if model
        running = described.find { |desc| RUNNING_SUBJECTS.include?(desc) }
        skip("#{running} (a running process) #{REASON}") if running
      end

      # Classes whose instances exist in a running system only: the tests
      # that describe them skip (their models are the gem's, see
      # Models::Deployment).
      RUNNING_SUBJECTS = [Syskit::Deployment].freeze

      # In an app's tests, mocks (the flexmock gem) stand for runtime
      # objects, as Syskit's bundles use them. Syskit's own harness
      # (syskit/test/self) mocks for real instead.
      module Mocks
        def flexmock(*)
          skip("flexmock #{REASON}")
        end
      end

      # Class-level statements of Syskit's test describe blocks.
      module ClassMethods
        # +run_live do ... end+ / +run_simulated do ... end+: how Syskit runs
        # the tests of the block. Their tests are kept; the runtime calls in
        # them skip.
        def run_live(&block)
          class_eval(&block) if block
        end

        def run_simulated(&block)
          class_eval(&block) if block
        end

        # +run_on_robot 'name'+: Roby's robot tests run on that robot's
        # configuration; what they do with it (execute_robot_controller)
        # needs the runtime and skips.
        def run_on_robot(_name); end
      end
    end
  end
end
