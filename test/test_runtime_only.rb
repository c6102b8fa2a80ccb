# frozen_string_literal: true

require 'helper'
require 'syskit/test/runtime_only'

module Syskit
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
