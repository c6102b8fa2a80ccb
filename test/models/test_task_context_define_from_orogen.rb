# frozen_string_literal: true

require 'helper'

module Syskit
  # The task model of an oroGen model made in Ruby
  # (Models.create_orogen_task_context_model, OroGen::Spec::TaskContext):
  # TaskContext.define_from_orogen, and its registration on OroGen.
  class TestTaskContextDefineFromOrogen < Minitest::Test
    include SelfTest::ModelsMadeInRuby

    def teardown
      TaskContext.clear_submodels
      ::OroGen.syskit_model_constant_registration = false
      ::OroGen.syskit_model_toplevel_constant_registration = false
      super
    end

    def test_the_model_stands_for_the_orogen_model_it_is_defined_from
      orogen = Models.create_orogen_task_context_model('define_test::Task')
      orogen.runtime_states :MOVING
      refute TaskContext.has_model_for?(orogen)
      model = TaskContext.define_from_orogen(orogen)
      assert_same orogen, model.orogen_model
      assert_same TaskContext, model.superclass
      assert TaskContext.has_model_for?(orogen)
      assert_same model, TaskContext.find_model_from_orogen_name('define_test::Task')
      assert_same model, TaskContext.define_from_orogen(orogen)
      assert_equal :moving, model.find_state_event(:MOVING)
    end

    def test_the_model_of_the_orogen_superclass_is_made_first_or_reused
      parent = Models.create_orogen_task_context_model('define_test::Parent')
      child = Models.create_orogen_task_context_model('define_test::Child', subclasses: parent)
      child_m = TaskContext.define_from_orogen(child, register: true)
      parent_m = TaskContext.find_model_by_orogen(parent)
      assert_same parent_m, child_m.superclass
      assert_same parent, child_m.orogen_model.superclass
      assert_same parent_m, ::OroGen.define_test.Parent

      other = Models.create_orogen_task_context_model('define_test::Other', subclasses: parent)
      assert_same parent_m, TaskContext.define_from_orogen(other).superclass

      TaskContext.clear_submodels
      refute ::OroGen.project_name?('define_test')
    end

    def test_a_registered_model_is_reached_by_its_call_chain_until_cleared
      project = ::OroGen::Spec::Project.new
      project.name 'define_test'
      orogen = ::OroGen::Spec::TaskContext.new(project, 'define_test::Task')
      model = TaskContext.define_from_orogen(orogen, register: true)
      assert_equal 'OroGen.define_test.Task', model.name
      assert_same model, ::OroGen.define_test.Task
      assert ::OroGen.project_name?('define_test')

      TaskContext.clear_submodels
      refute ::OroGen.project_name?('define_test')
      refute_respond_to ::OroGen, :define_test
    end

    def test_constant_registration_makes_the_project_a_constant_too
      ::OroGen.syskit_model_constant_registration = true
      ::OroGen.syskit_model_toplevel_constant_registration = true
      model = TaskContext.define_from_orogen(Models.create_orogen_task_context_model('define_test::Task'),
                                             register: true)
      assert_same model, ::OroGen::DefineTest::Task
      assert_same model, ::DefineTest::Task
      TaskContext.clear_submodels
      refute ::OroGen.const_defined?(:DefineTest, false)
      refute Object.const_defined?(:DefineTest, false)
    end

    def test_a_model_class_may_register_its_submodels_elsewhere
      namespace = Module.new.extend(OroGenNamespace)
      klass = Class.new(TaskContext)
      klass.define_singleton_method(:register_model) { namespace.register_syskit_model(self) }
      model = klass.define_from_orogen(Models.create_orogen_task_context_model('define_test::Task'), register: true)
      assert_same klass, model.superclass
      assert_same model, namespace.define_test.Task
      refute ::OroGen.project_name?('define_test')
    end
  end
end
