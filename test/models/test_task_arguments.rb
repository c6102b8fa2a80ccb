# frozen_string_literal: true

require 'helper'
require 'syskit/test/plan'

module Syskit
  # A task's arguments as Syskit's (Roby's): its configuration sections
  # are the +conf+ argument, a task context has a +read_only+ argument,
  # and declared defaults are there from the start without counting as set.
  class TestTaskArguments < Minitest::Test
    def setup
      @task_m = TaskContext.new_submodel(name: 'Pump') { argument :rate, default: 10 }
    end

    def test_a_new_task_has_its_declared_defaults_not_set
      task = @task_m.new
      assert_equal Compat::Roby::DefaultArgument.new(%w[default]), task.arguments[:conf]
      assert_equal Compat::Roby::DefaultArgument.new(false), task.arguments[:read_only]
      assert_equal Compat::Roby::DefaultArgument.new(10), task.arguments[:rate]
      assert_empty task.arguments.each_assigned_argument.to_a
      assert_equal %w[default], task.conf
      refute task.read_only
      assert_equal 10, task.rate
    end

    def test_conf_is_the_conf_argument
      task = @task_m.new(conf: %w[default slow])
      assert_equal %w[default slow], task.arguments[:conf]
      assert task.arguments.set?(:conf)
      task.conf = %w[fast]
      assert_equal %w[fast], task.arguments[:conf]
      assert_equal %w[fast], task.conf
    end

    def test_fullfilled_model_has_the_arguments_that_are_set
      task = @task_m.new(conf: %w[slow], rate: 3)
      assert_equal [[@task_m], { conf: %w[slow], rate: 3 }], task.fullfilled_model
      assert_equal [[@task_m], {}], @task_m.new.fullfilled_model
    end

    def test_instanciate_sets_the_conf_it_is_given
      plan = Test::Plan.new
      task = @task_m.instanciate(plan, DependencyInjectionContext.new, task_arguments: { conf: %w[slow] })
      assert_equal({ conf: %w[slow], read_only: Compat::Roby::DefaultArgument.new(false),
                     rate: Compat::Roby::DefaultArgument.new(10) }, task.arguments)
      assert_equal [[@task_m], { conf: %w[slow] }], task.fullfilled_model
    end

    def test_a_task_made_with_the_default_sections_leaves_conf_unset
      task = @task_m.instanciate(Test::Plan.new)
      refute task.arguments.set?(:conf)
      assert_equal %w[default], task.conf
      chosen = @task_m.with_conf('default').instanciate(Test::Plan.new)
      assert chosen.arguments.set?(:conf)
    end

    def test_a_conf_argument_given_to_requirements_is_their_sections
      requirements = @task_m.with_arguments(conf: %w[default slow], rate: 2)
      assert_equal %w[default slow], requirements.conf
      assert_equal({ rate: 2 }, requirements.arguments)
      task = requirements.instanciate(Test::Plan.new)
      assert_equal %w[default slow], task.conf
    end

    def test_a_task_made_from_another_ones_arguments_keeps_defaults_unset
      task = @task_m.new(@task_m.new(rate: 2).arguments)
      assert_equal 2, task.rate
      refute task.arguments.set?(:conf)
    end

    def test_every_task_arguments_are_not_listed_with_the_models_own
      assert_equal({ rate: 10 }, @task_m.argument_defaults)
      assert @task_m.has_argument?(:conf)
      assert @task_m.has_argument?(:read_only)
      cmp_m = Composition.new_submodel(name: 'Cmp')
      assert_equal({}, cmp_m.argument_defaults)
      refute cmp_m.has_argument?(:read_only)
    end

    # A model's defaults are kept between its tasks: an argument declared
    # later, here or on a parent model, still reaches the tasks made after.
    def test_an_argument_declared_after_a_task_was_made_reaches_the_next_tasks
      child_m = @task_m.new_submodel(name: 'SlowPump')
      assert_nil child_m.new.arguments[:pressure]
      @task_m.argument :pressure, default: 2
      assert_equal Compat::Roby::DefaultArgument.new(2), child_m.new.arguments[:pressure]
      child_m.argument :rate, default: 1
      assert_equal Compat::Roby::DefaultArgument.new(1), child_m.new.arguments[:rate]
      assert_equal Compat::Roby::DefaultArgument.new(10), @task_m.new.arguments[:rate]
    end

    # Tasks share their model's defaults, never what another task set.
    def test_setting_an_argument_changes_only_that_task
      first = @task_m.new
      first.rate = 3
      assert_equal 3, first.rate
      assert first.arguments.set?(:rate)
      assert_equal 10, @task_m.new.rate
      refute @task_m.new.arguments.set?(:rate)
    end

    def test_requirements_of_a_task_carry_its_sections_as_sections
      requirements = @task_m.new(conf: %w[slow], rate: 3).to_instance_requirements
      assert_equal %w[slow], requirements.conf
      assert_equal({ rate: 3 }, requirements.arguments)
    end
  end
end
