# frozen_string_literal: true

require 'helper'

module Syskit
  # Ports of task models made in Ruby (Syskit::TaskContext.new_submodel):
  # dynamic ports, and ports declared through orogen_model as Syskit's
  # tests do.
  class TestRubyTaskPorts < Minitest::Test
    include SelfTest::ModelsMadeInRuby

    def test_dynamic_ports_match_names_and_types
      model = TaskContext.new_submodel do
        dynamic_input_port(/^w\w+$/, '/double')
        dynamic_output_port(/^\w+$/)
      end
      double = Syskit.app.types.find('/double')
      assert model.spec.dynamic_port_for(:input, 'wdev', double)
      refute model.spec.dynamic_port_for(:input, 'dev', double)
      assert model.spec.dynamic_port_for(:output, 'dev', Syskit.app.types.find('/float'))
    end

    def test_a_dynamic_port_name_may_be_a_string_pattern_as_in_syskits_tests
      model = TaskContext.new_submodel { dynamic_input_port 'w.*', '/double' }
      assert model.spec.dynamic_port_for(:input, 'wheel', Syskit.app.types.find('/double'))
    end

    def test_dynamic_ports_declared_through_the_orogen_model
      model = TaskContext.new_submodel
      model.orogen_model.dynamic_input_port(/^in_/, '/double')
      model.orogen_model.dynamic_output_port(/^out_/)
      assert_equal %i[input output], model.orogen_model.dynamic_ports.map(&:direction)
      assert model.spec.dynamic_port_for(:input, 'in_a', Syskit.app.types.find('/double'))
    end

    def test_states_are_declared_as_in_an_orogen_file
      model = TaskContext.new_submodel do
        runtime_states :moving
        reports :blocked
        error_states :stalled
      end
      assert_equal %w[moving blocked], model.spec.states[:runtime_states]
      assert_equal %w[stalled], model.spec.states[:error_states]
    end

    def test_the_orogen_model_may_be_named_apart_from_the_model
      model = TaskContext.new_submodel(orogen_model_name: 'test::Task') { output_port 'out', '/double' }
      assert_equal 'test::Task', model.orogen_model.name
      assert_match(/anonymous ruby task/, model.name)
      assert_equal 'Probe', TaskContext.new_submodel(name: 'Probe').orogen_model.name
    end

    def test_ports_declared_through_the_orogen_model
      model = TaskContext.new_submodel
      model.orogen_model.input_port 'frames_in', '/double'
      model.orogen_model.output_port 'frames_out', '/double'
      assert_equal %w[frames_in frames_out state], model.ports.keys.sort
      assert model.find_input_port('frames_in')
    end

    def test_an_orogen_task_model_gets_its_ports_from_its_orogen_file
      Syskit.app.orogen.load_library('imu', nil)
      error = assert_raises(ArgumentError) { OroGen.imu.Task.orogen_model.input_port 'x', '/double' }
      assert_match(/input_port on the oroGen model of imu::Task: its ports are declared in its .orogen file/,
                   error.message)
    end

    def test_a_task_finds_its_ports_as_task_ports_and_their_declarations_apart
      model = TaskContext.new_submodel do
        output_port 'out', '/double'
        dynamic_output_port(/^dev\w*$/, '/double')
      end
      task = model.new
      assert_kind_of Port, task.find_port('out')
      assert_equal task.out_port, task.find_port(:out)
      assert_same task, task.find_port('out').component
      assert_same model.spec.find_port('out'), task.find_orogen_port('out')
      assert_nil task.find_port('none')
      created = task.create_port(:output, 'dev0', '/double')
      assert_same created, task.find_orogen_port('dev0')
      assert_equal 'dev0', task.find_port('dev0').name
    end
  end
end
