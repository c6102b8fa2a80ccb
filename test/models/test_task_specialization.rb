# frozen_string_literal: true

require 'helper'

module Syskit
  # Syskit's +task.specialize+: a task held in a plan gets a model of its
  # own, to which services can be added without touching the model it was
  # made from, and which it is still known by (concrete_model,
  # provided_models, fullfilled_model).
  class TestTaskSpecialization < Minitest::Test
    def setup
      double = Types::OpaqueType.new('/double')
      @srv_m = DataService.new_submodel(name: 'Pose') { output_port 'pose', double }
      @task_m = TaskContext.new_submodel(name: 'Odometry') { output_port 'pose', double }
    end

    def test_a_plain_task_is_of_its_class_and_not_specialized
      task = @task_m.new
      assert_same @task_m, task.model
      assert_same @task_m, task.concrete_model
      refute task.specialized_model?
      assert_equal [@task_m], task.provided_models
    end

    def test_specialize_gives_the_task_a_model_of_its_own_once
      task = @task_m.new
      assert task.specialize
      own = task.model
      refute_same @task_m, own
      assert own < @task_m
      assert task.specialized_model?
      refute task.specialize
      assert_same own, task.model
    end

    def test_the_task_is_still_known_by_the_model_it_was_made_from
      task = @task_m.new
      task.specialize
      assert_same @task_m, task.concrete_model
      assert_equal [@task_m], task.provided_models
      assert_equal [[@task_m], {}], task.fullfilled_model
      other = @task_m.specialize.new
      assert other.specialized_model?
      assert_equal [@task_m], other.provided_models
    end

    def test_the_ports_of_a_service_of_a_specialized_task_are_those_of_its_own_model
      @task_m.provides @srv_m, as: 'pose'
      task = @task_m.new
      assert_same @task_m.pose_srv, task.pose_srv.pose_port.model.component_model
      task.specialize
      port = task.pose_srv.pose_port
      assert_same task.model, port.model.component_model.component_model
      assert_equal 'pose', port.name
      assert_equal task.pose_port, port.to_component_port
    end

    def test_services_added_to_the_own_model_leave_the_task_model_alone
      task = @task_m.new
      task.specialize
      task.model.provides @srv_m, as: 'pose'
      assert task.fullfills?(@srv_m)
      refute @task_m.fullfills?(@srv_m)
      assert_same task.model, task.find_data_service('pose').model.component_model
      assert_same task.model, task.pose_port.model.component_model
    end

    def test_require_dynamic_service_on_a_task_adds_the_service_to_its_own_model_only
      marker = DataService.new_submodel(name: 'Marker')
      @task_m.dynamic_service(marker, as: 'dyn') { provides marker, as: name }
      task = @task_m.new
      srv = task.require_dynamic_service('dyn', as: 'left')
      assert task.specialized_model?
      assert_same srv, task.find_data_service('left')
      assert_same task.model, srv.model.component_model
      assert_same srv, task.require_dynamic_service('dyn', as: 'left')
      assert_nil @task_m.find_data_service('left')
      assert_nil @task_m.new.find_data_service('left')
    end

    def test_require_dynamic_service_on_a_task_raises_argument_errors
      task = @task_m.new
      assert_raises(ArgumentError) { task.require_dynamic_service('nothing', as: 'x') }
      assert_raises(ArgumentError) { task.require_dynamic_service('nothing') }
    end

    def test_to_instance_requirements_keeps_the_set_arguments_only
      model = Component.new_submodel do
        argument :rate
        argument :mode, default: nil
        argument :offset
      end
      task = model.new(rate: 10, offset: Compat::Roby::DefaultArgument.new(2))
      req = task.to_instance_requirements
      assert_equal({ rate: 10 }, req.arguments.to_hash)
      assert req.fullfills?(model)
    end

    def test_plain_component_tasks_can_be_specialized_too
      task = Component.new_submodel.new
      assert task.specialize
      assert task.specialized_model?
    end
  end
end
