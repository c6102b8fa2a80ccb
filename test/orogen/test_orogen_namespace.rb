# frozen_string_literal: true

require 'helper'

module Syskit
  # Syskit's OroGenNamespace on a module of one's own: models registered
  # by their oroGen name are reached as namespace.project.Task.
  class TestOroGenNamespace < Minitest::Test
    Project = Struct.new(:name)
    Spec = Struct.new(:project, :name)
    Model = Struct.new(:orogen_model)

    def setup
      super
      @namespace = Module.new.extend(OroGenNamespace)
      @namespace.define_singleton_method(:name) { 'Ns' }
    end

    def model(orogen_name)
      Model.new(Spec.new(Project.new(orogen_name.split('::').first), orogen_name))
    end

    def test_a_registered_model_is_reached_by_project_and_name_and_its_call_chain_returned
      task = model('project::Task')
      assert_equal 'Ns.project.Task', @namespace.register_syskit_model(task)
      assert_same task, @namespace.project.Task
      assert_same task, @namespace.syskit_model_by_orogen_name('project::Task')
      assert @namespace.project_name?('project')
      refute @namespace.project_name?('other')
    end

    def test_namespaces_inside_a_project_are_reached_by_method_too
      task = model('project::inner::Task')
      @namespace.register_syskit_model(task)
      assert_same task, @namespace.project.inner.Task
    end

    def test_a_model_takes_no_arguments
      @namespace.register_syskit_model(model('project::Task'))
      error = assert_raises(ArgumentError) { @namespace.project.Task('x') }
      assert_equal 'expected 0 arguments, got 1', error.message
      error = assert_raises(ArgumentError) { @namespace.project.Task(nil, false) }
      assert_equal 'expected 0 arguments, got 2', error.message
    end

    def test_the_project_is_a_constant_only_when_constant_registration_is_on
      @namespace.register_syskit_model(model('project::Task'))
      refute @namespace.const_defined?(:Project, false)

      other = Module.new.extend(OroGenNamespace)
      other.syskit_model_constant_registration = true
      task = model('project::Task')
      other.register_syskit_model(task)
      assert_same task, other::Project::Task
    end

    def test_an_unregistered_name_is_an_argument_error
      assert_raises(ArgumentError) { @namespace.syskit_model_by_orogen_name('project::Task') }
    end
  end
end
