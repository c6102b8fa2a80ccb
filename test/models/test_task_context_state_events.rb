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
  end
end
