# frozen_string_literal: true

require 'helper'
require 'syskit/test/plan'

module Syskit
  # Model-level data_reader / data_writer: a component model names the
  # ports it reads or writes while it runs, and each of its tasks has one
  # accessor per name.
  class TestDataAccessors < Minitest::Test
    def setup
      double = Types::OpaqueType.new('/double')
      @source_m = TaskContext.new_submodel(name: 'Source') do
        input_port 'cmd', double
        output_port 'pose', double
      end
      @user_m = TaskContext.new_submodel(name: 'User')
    end

    def test_a_model_declares_readers_and_writers
      reader_m = @user_m.data_reader @source_m.match.pose_port, as: 'pose'
      writer_m = @user_m.data_writer @source_m.cmd_port, as: 'cmd'
      assert_equal [reader_m], @user_m.each_data_reader.to_a
      assert_equal [writer_m], @user_m.each_data_writer.to_a
      assert_same reader_m, @user_m.find_data_reader('pose')
    end

    def test_each_task_has_one_accessor_per_declaration
      @user_m.data_reader @source_m.match.pose_port, as: 'pose'
      @user_m.data_writer @source_m.cmd_port, as: 'cmd'
      task = @user_m.new
      reader = task.pose_reader
      assert_kind_of DynamicPortBinding::BoundOutputReader, reader
      assert_kind_of DynamicPortBinding::BoundInputWriter, task.cmd_writer
      assert_same reader, task.find_data_reader('pose'), 'one accessor per task and name'
      assert_equal [reader], task.each_data_reader.to_a
      assert_equal [task.cmd_writer], task.each_data_writer.to_a
      assert_equal ['pose', task], [reader.name, reader.component]
      refute_same reader, @user_m.new.pose_reader
      assert_nil task.find_data_writer('pose')
    end

    def test_submodels_inherit_the_accessors
      @user_m.data_reader @source_m.pose_port, as: 'pose'
      sub = @user_m.new_submodel
      sub.data_writer @source_m.cmd_port, as: 'cmd'
      assert_equal ['pose'], sub.each_data_reader.map(&:name)
      assert_empty @user_m.each_data_writer.to_a
      assert sub.new.pose_reader
    end

    def test_a_reader_of_an_input_port_is_an_argument_error
      error = assert_raises(ArgumentError) { @user_m.data_reader @source_m.match.cmd_port, as: 'cmd' }
      assert_match(/is an input port, data_reader expects an output port/, error.message)
      assert_equal File.expand_path(__FILE__), error.location.path
      assert_raises(ArgumentError) { @user_m.data_writer @source_m.pose_port, as: 'pose' }
      assert_raises(ArgumentError) { @user_m.data_reader 'pose', as: 'pose' }
    end

    def test_a_running_matcher_finds_nothing_in_a_plan_held_as_data
      plan = Test::Plan.new
      plan.add(@source_m.new)
      assert_equal 1, @source_m.match.to_a(plan).size
      assert_empty @source_m.match.running.to_a(plan)
      assert @source_m.match.running.pose_port
    end
  end
end
