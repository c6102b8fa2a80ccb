# frozen_string_literal: true

require 'helper'
require 'syskit/test/plan'

module Syskit
  # Syskit's can_merge? and merge on tasks held in a plan as data: whether
  # one task may stand for another, and what it takes from it.
  class TestTaskMerging < Minitest::Test
    def setup
      marker = @marker = DataService.new_submodel(name: 'Marker')
      @task_m = TaskContext.new_submodel(name: 'Camera') do
        argument :exposure
        dynamic_service(marker, as: 'dyn') { provides marker.new_submodel, as: name }
      end
    end

    def test_tasks_of_one_model_merge_whatever_services_they_required
      left = @task_m.new
      right = @task_m.new
      assert left.can_merge?(right)
      right.require_dynamic_service('dyn', as: 'a')
      assert left.can_merge?(right)
      left.require_dynamic_service('dyn', as: 'b')
      assert left.can_merge?(right)
    end

    def test_services_of_one_name_but_different_models_do_not_merge
      left = @task_m.new
      right = @task_m.new
      left.require_dynamic_service('dyn', as: 'a')
      right.require_dynamic_service('dyn', as: 'a')
      refute left.can_merge?(right)
    end

    def test_an_abstract_task_does_not_stand_for_a_concrete_one
      left = @task_m.new
      right = @task_m.new
      left.abstract = true
      refute left.can_merge?(right)
      assert right.can_merge?(left)
    end

    def test_arguments_set_on_both_must_be_equal
      left = @task_m.new
      right = @task_m.new(exposure: 10)
      assert left.can_merge?(right)
      left.exposure = 5
      refute left.can_merge?(right)
      left.exposure = 10
      assert left.can_merge?(right)
    end

    def test_merge_takes_missing_arguments_and_services_on_its_own_model
      left = @task_m.new
      right = @task_m.new(exposure: 3)
      right.require_dynamic_service('dyn', as: 'a')
      assert_same left, left.merge(right)
      assert_equal 3, left.arguments[:exposure]
      assert left.specialized_model?
      assert left.find_data_service('a')
      assert_nil @task_m.find_data_service('a')
    end

    def test_default_arguments_are_not_set_and_go_only_where_nothing_is
      default = Compat::Roby::DefaultArgument.new(7)
      refute @task_m.new(exposure: default).arguments.set?(:exposure)
      bare = @task_m.new
      bare.merge(@task_m.new(exposure: default))
      assert_equal default, bare.arguments.values[:exposure]
    end

    def test_each_assigned_argument_lists_only_the_arguments_that_are_set
      default = Compat::Roby::DefaultArgument.new(7)
      task_m = TaskContext.new_submodel(name: 'Lidar') do
        argument :range
        argument :rate
      end
      task = task_m.new(range: default, rate: 10)
      assert_equal [[:rate, 10]], task.arguments.each_assigned_argument.to_a
    end

    def test_a_default_argument_gives_way_to_what_the_task_has
      default = Compat::Roby::DefaultArgument.new(7)
      own_default = Compat::Roby::DefaultArgument.new(8)
      defaulted = @task_m.new(exposure: own_default)
      defaulted.merge(@task_m.new(exposure: default))
      assert_equal own_default, defaulted.arguments[:exposure]
      defaulted.merge(@task_m.new(exposure: 9))
      assert_equal 9, defaulted.arguments[:exposure]
      static = @task_m.new(exposure: 1)
      static.merge(@task_m.new(exposure: default))
      assert_equal 1, static.arguments[:exposure]
    end

    def test_merge_leaves_a_task_without_dynamic_services_unspecialized
      left = @task_m.new(exposure: 1)
      left.merge(@task_m.new(exposure: 2))
      refute left.specialized_model?
      assert_equal 1, left.arguments[:exposure]
    end

    def test_children_given_roby_task_from_parent_task_take_their_compositions_argument
      cmp_m = Composition.new_submodel
      cmp_m.argument :exposure
      cmp_m.add(@task_m, as: 'camera').with_arguments(exposure: Compat::Roby::Task.from(:parent_task).exposure)
      plan = Test::Plan.new
      short = cmp_m.with_arguments(exposure: 1).instanciate(plan).camera_child
      long = cmp_m.with_arguments(exposure: 5).instanciate(plan).camera_child
      other = cmp_m.with_arguments(exposure: 5).instanciate(plan).camera_child
      assert_equal [1, 5], [short.exposure, long.exposure]
      refute short.can_merge?(long)
      assert long.can_merge?(other)
    end

    def test_tasks_bound_to_different_hosts_do_not_merge
      left = @task_m.new
      right = @task_m.new
      left.required_host = 'host'
      assert left.can_merge?(right)
      assert right.can_merge?(left)
      right.required_host = 'other'
      refute left.can_merge?(right)
      right.required_host = 'host'
      assert left.can_merge?(right)
    end
  end
end
