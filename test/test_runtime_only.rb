# frozen_string_literal: true

require 'helper'
require 'syskit/test/runtime_only'

module Syskit
  # What tasks and ports do only in a running system skips the test that
  # asks for it (Test::RuntimeOnly), saying so, while what they are as
  # data still answers.
  class TestRuntimeOnly < Minitest::Test
    def setup
      double = Types::OpaqueType.new('/double')
      @task_m = TaskContext.new_submodel do
        input_port 'in', double
        output_port 'out', double
      end
    end

    def test_setting_a_task_up_skips
      task = @task_m.new
      %i[setup ready_for_setup?].each do |name|
        skip = assert_raises(Minitest::Skip) { task.public_send(name) }
        assert_equal "task.#{name} needs Syskit's runtime (Roby and Orocos)", skip.message
      end
      assert_raises(Minitest::Skip) { task.fullfilled_model = [Component, [], {}] }
      assert_equal [[@task_m], {}], task.fullfilled_model
    end

    def test_reading_or_writing_a_port_skips
      task = @task_m.new
      assert_match(/port.reader needs Syskit's runtime/, assert_raises(Minitest::Skip) { task.out_port.reader }.message)
      assert_match(/port.writer needs Syskit's runtime/, assert_raises(Minitest::Skip) { task.in_port.writer }.message)
      assert_equal 'out', task.out_port.name
    end
  end

  # Roby's capture_log in Syskit's tests: the block is model-level code,
  # and runs; nothing logs through Roby's loggers here.
  class TestRuntimeOnlyCaptureLog < Minitest::Test
    include Test::RuntimeOnly

    def test_capture_log_runs_its_block_and_captures_nothing
      ran = false
      assert_equal [], capture_log(Syskit, :fatal) { ran = true }
      assert ran
    end

    def test_a_runtime_call_in_the_block_still_skips
      skip_error = assert_raises(Minitest::Skip) { capture_log(Syskit, :warn) { execution_engine } }
      assert_equal "execution_engine needs Syskit's runtime (Roby and Orocos)", skip_error.message
    end
  end
end
