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
end
