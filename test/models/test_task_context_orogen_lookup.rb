# frozen_string_literal: true

require 'helper'

module Syskit
  # Finding the task model that stands for an oroGen model: model_for,
  # find_model_by_orogen, has_model_for? and find_model_from_orogen_name.
  class TestTaskContextOrogenLookup < Minitest::Test
    include SelfTest::ModelsMadeInRuby

    def test_a_submodel_is_found_from_its_orogen_model
      model = TaskContext.new_submodel(orogen_model_name: 'lookup_test::Task')
      assert TaskContext.has_model_for?(model.orogen_model)
      assert_same model, TaskContext.model_for(model.orogen_model)
      assert_same model, TaskContext.find_model_by_orogen(model.spec)
      assert_same model, TaskContext.find_model_from_orogen_name('lookup_test::Task')
    end

    def test_an_unknown_orogen_model_is_not_found
      other = Orogen::ModelView.new(Orogen::TaskSpec.new('lookup_test::Other', nil))
      refute TaskContext.has_model_for?(other)
      assert_nil TaskContext.find_model_by_orogen(other)
      assert_nil TaskContext.find_model_from_orogen_name('lookup_test::Missing')
      error = assert_raises(ArgumentError) { TaskContext.model_for(other) }
      assert_kind_of UnknownName, error
    end

    def test_the_orogen_model_finds_ports_by_direction
      model = TaskContext.new_submodel do
        input_port 'cmd', '/double'
        output_port 'status', '/double'
      end
      assert_equal 'cmd', model.orogen_model.find_input_port('cmd').name
      assert_nil model.orogen_model.find_input_port('status')
      assert_equal 'status', model.orogen_model.find_output_port(:status).name
      assert_nil model.orogen_model.find_output_port('cmd')
      assert_nil model.orogen_model.find_output_port('none')
    end

    def test_rtt_task_context_is_the_root_task_model
      assert_same TaskContext, OroGen::RTT::TaskContext
      model = OroGen::RTT::TaskContext.new_submodel
      assert TaskContext.has_submodel?(model)
    end

    def test_a_specialized_model_has_its_own_orogen_model
      model = TaskContext.new_submodel
      specialized = model.specialize
      assert_same model.orogen_model, specialized.orogen_model.superclass
      specialized.orogen_model.output_port 'extra', '/double'
      assert specialized.orogen_model.has_port?('extra')
      refute model.orogen_model.has_port?('extra')
    end

    def test_a_forgotten_submodel_is_not_found
      model = TaskContext.new_submodel
      sub = model.new_submodel
      model.clear_submodels
      refute TaskContext.has_model_for?(sub.orogen_model)
      assert TaskContext.has_model_for?(model.orogen_model)
    end
  end
end
