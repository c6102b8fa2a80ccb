# frozen_string_literal: true

require 'helper'

module Syskit
  # The events task models have for their states (state_events,
  # find_state_event), from RTT's states and those their specs declare.
  class TestTaskContextStateEvents < Minitest::Test
    include SelfTest::ModelsMadeInRuby

    def test_rtt_states_have_events_but_pre_operational
      assert_equal :fatal_error, TaskContext.find_state_event(:FATAL_ERROR)
      assert_equal :stopped, TaskContext.find_state_event('STOPPED')
      assert_nil TaskContext.find_state_event(:PRE_OPERATIONAL)
    end

    def test_declared_states_have_events_in_submodels_too
      parent = TaskContext.new_submodel do
        runtime_states :GOING_UP
        error_states :STUCK
      end
      child = parent.new_submodel
      assert_equal :going_up, child.find_state_event(:GOING_UP)
      assert_equal :stuck, parent.find_state_event(:STUCK)
      assert_nil TaskContext.find_state_event(:STUCK)
    end

    def test_a_task_finds_the_events_of_its_model_states
      child = TaskContext.new_submodel { runtime_states :GOING_UP }.new_submodel
      assert_equal :going_up, child.new.state_event(:GOING_UP)
      assert_nil child.new.state_event(:PRE_OPERATIONAL)
    end

    def test_declared_states_have_events_forwarded_to_rtt_s_of_their_kind
      orogen = Models.create_orogen_task_context_model('events_test::Task')
      orogen.error_states :BLOCKED
      orogen.fatal_states :BROKEN
      model = TaskContext.define_from_orogen(orogen)
      orogen.runtime_states :MOVING
      assert_equal [false, true, false, true], [model.blocked_event, model.broken_event, model.moving_event,
                                                model.exception_event].map(&:terminal?)
      assert_equal :runtime_error, model.find_event(:blocked).forwarded_to
      assert_nil model.find_event(:pre_operational)
      assert_forwarding(model)
    ensure
      TaskContext.clear_submodels
    end

    def assert_forwarding(model)
      task = model.new
      forwarding = Roby::EventStructure::Forwarding
      assert task.blocked_event.child_object?(task.runtime_error_event, forwarding)
      assert task.broken_event.child_object?(task.fatal_error_event, forwarding)
      refute task.broken_event.child_object?(task.runtime_error_event, forwarding)
      refute task.moving_event.child_object?(task.running_event, forwarding)
      refute task.blocked_event.child_object?(model.new.runtime_error_event, forwarding)
    end

    def test_states_declared_in_ruby_have_event_readers_on_the_model_and_its_tasks
      model = TaskContext.new_submodel { exception_states :JAMMED }
      assert model.jammed_event.terminal?
      assert_equal model.new.jammed_event.model, model.jammed_event
    end
  end
end
