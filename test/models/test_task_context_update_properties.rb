# frozen_string_literal: true

require 'helper'

module Syskit
  # TaskContext.use_update_properties?: which configuration hook a task
  # model relies on, from the methods its own classes define.
  class TestTaskContextUpdateProperties < Minitest::Test
    include SelfTest::ModelsMadeInRuby

    def test_a_model_without_hooks_uses_update_properties
      assert TaskContext.new_submodel.use_update_properties?
    end

    def test_a_model_defining_configure_does_not
      model = TaskContext.new_submodel
      model.class_eval { def configure; end }
      refute model.use_update_properties?
      refute model.new_submodel.use_update_properties?
    end

    def test_update_properties_wins_over_configure
      model = TaskContext.new_submodel
      model.class_eval { def configure; end }
      assert model.new_submodel.tap { |m| m.class_eval { def update_properties; end } }.use_update_properties?
    end

    def test_a_prepended_module_does_not_count
      model = TaskContext.new_submodel
      model.class_eval { def configure; end }
      model.prepend(Module.new { def update_properties; end })
      refute model.use_update_properties?
    end

    # The answer is kept per model, and follows hooks defined or removed
    # afterwards, in the model or in a parent.
    def test_the_answer_follows_hooks_defined_later
      parent = TaskContext.new_submodel
      child = parent.new_submodel
      assert child.use_update_properties?
      parent.class_eval { def configure; end }
      refute child.use_update_properties?
      child.class_eval { def update_properties; end }
      assert child.use_update_properties?
      child.send(:remove_method, :update_properties)
      refute child.use_update_properties?
    end
  end
end
