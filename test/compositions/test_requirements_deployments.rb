# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'syskit/test/plan'

module Syskit
  # What requirements say of their deployments, as Syskit's: their
  # deployment hints and group are theirs to add to, a copy (dup) has its
  # own, frozen requirements (what a profile or an injection holds) refuse
  # changes, and a task made alone has requirements of its own too.
  class TestRequirementsDeployments < Minitest::Test
    include CompositionTestHelper

    def setup
      super
      load_rig({}, profile: "profile 'Base' do\n#{ROBOT.gsub(/^/, '  ')}end\n")
      @task_m = TaskContext.new_submodel(name: 'Cam')
    end

    def test_hints_are_added_to_the_requirements_and_a_copy_has_its_own
      requirements = InstanceRequirements.new([@task_m])
      requirements.deployment_hints << /front/
      assert_equal [/front/], requirements.deployment_hints
      assert_same requirements, requirements.prefer_deployed_tasks(/front/, 'rear')
      assert_equal [/front/, 'rear'], requirements.deployment_hints
      copy = requirements.dup
      copy.deployment_hints << 'side'
      assert_equal [/front/, 'rear'], requirements.deployment_hints
      assert_equal [/front/, 'rear', 'side'], copy.deployment_hints
    end

    def test_held_requirements_keep_their_hints
      requirements = @task_m.prefer_deployed_tasks('front')
      DependencyInjection.new('cam' => requirements)
      assert_raises(FrozenError) { requirements.deployment_hints << 'rear' }
      changed = requirements.prefer_deployed_tasks('rear')
      assert_equal %w[front rear], changed.deployment_hints
      assert_equal %w[front], requirements.deployment_hints
    end

    # A definition does not change when the requirements it was made from
    # do afterwards.
    def test_definitions_keep_the_hints_they_were_defined_with
      requirements = @task_m.to_instance_requirements
      profile = Actions::Profile.new('Cams')
      profile.define 'plain', requirements
      profile.define 'front', requirements.prefer_deployed_tasks('front')
      assert_empty profile.plain_def.deployment_hints
      assert_equal %w[front], profile.front_def.deployment_hints
      assert_raises(FrozenError) { profile.front_def.deployment_hints << 'rear' }
    end

    # A profile's device action is held: it keeps the device's hints, and
    # has nothing of its own to add to.
    def test_a_device_action_has_no_hints_or_group_to_add_to
      left = Rig::Profiles::Base.left_wheel_dev
      assert_equal %w[left_wheel], left.deployment_hints
      assert_raises(FrozenError) { left.deployment_hints << 'front' }
      gps = Rig::Profiles::Base.gps_dev
      assert_raises(FrozenError) { gps.deployment_hints << 'front' }
      assert_raises(FrozenError) { gps.deployment_group.use_deployment(OroGen.rig.Tracker => 'gps_tracker') }
      assert_empty Rig::Profiles::Base.gps_dev.deployment_hints
      assert_equal %w[front], gps.prefer_deployed_tasks('front').deployment_hints
    end

    def test_a_task_made_alone_has_requirements_to_add_hints_to
      task = @task_m.new
      assert_kind_of InstanceRequirements, task.requirements
      assert_empty task.deployment_hints
      task.requirements.deployment_hints << 'front'
      assert_equal %w[front], task.deployment_hints
      assert_empty @task_m.new.requirements.deployment_hints
      refute task.abstract?
    end

    # Without hints of its own, a task has those of the compositions it is
    # a child of.
    def test_a_task_without_hints_has_its_parents
      child = Component.new
      cmp_m = Composition.new_submodel(name: 'Rig')
      parents = [%w[a b], %w[b c]].map do |hints|
        parent = cmp_m.new
        parent.requirements.deployment_hints.concat(hints)
        parent.depends_on(child, role: 'cam')
        parent
      end
      assert_equal %w[a b c], child.deployment_hints
      child.requirements.deployment_hints << 'own'
      assert_equal %w[own], child.deployment_hints
      refute_nil parents
    end

    def test_deployments_added_to_the_group_of_requirements_deploy_their_task
      ruby_m = RubyTaskContext.new_submodel(name: 'Gen')
      requirements = InstanceRequirements.new([ruby_m])
      deployments = requirements.deployment_group.use_ruby_tasks(ruby_m => 'gen')
      assert_equal %w[gen], deployments.map(&:name)
      task = requirements.instanciate(Test::Plan.new)
      found = task.requirements.deployment_group.find_all_suitable_deployments_for(task)
      assert_equal [[deployments.first, 'gen']], found.map(&:to_a)
      assert_empty InstanceRequirements.new([ruby_m]).deployment_group.find_all_suitable_deployments_for(task)
    end

    def test_a_copy_has_its_own_group_and_held_requirements_a_frozen_one
      ruby_m = RubyTaskContext.new_submodel(name: 'Gen')
      requirements = InstanceRequirements.new([ruby_m])
      requirements.deployment_group.use_ruby_tasks(ruby_m => 'gen')
      copy = requirements.dup
      copy.deployment_group.use_ruby_tasks(ruby_m => 'other_gen')
      assert_equal %w[gen], requirements.deployment_group.deployed_tasks.map(&:name)
      DependencyInjection.new('gen' => requirements)
      assert_raises(FrozenError) { requirements.deployment_group.use_ruby_tasks(ruby_m => 'third_gen') }
      assert_equal [ruby_m], requirements.deployment_group.deployed_tasks_for(ruby_m).map(&:model)
    end

    # Requirements on a composition stand for what they require.
    def test_a_model_fullfills_requirements_when_it_fullfills_their_models
      cmp_m = Composition.new_submodel(name: 'Rig') { add Rig::Services::Pose, as: 'pose' }
      assert cmp_m.new_submodel.fullfills?(cmp_m.use('pose' => OroGen.rig.Tracker.front_pose_srv))
      refute @task_m.fullfills?(cmp_m.to_instance_requirements)
    end
  end
end
