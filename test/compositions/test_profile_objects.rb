# frozen_string_literal: true

require 'helper'

module Syskit
  # Profiles made in Ruby as Syskit's tests make them, without a module:
  # +Actions::Profile.new('name')+ answers its actions itself.
  class TestProfileObjects < Minitest::Test
    def setup
      super
      @pose = DataService.new_submodel(name: 'Pose')
      @task = TaskContext.new_submodel(name: 'Task')
    end

    def test_a_profile_is_registered_when_asked_or_made_by_the_profile_statement
      named = Actions::Profile.new('Named')
      assert_equal 'Named', named.name
      refute_includes Actions::Profile.each_submodel.to_a, named
      registered = Actions::Profile.new(register: true)
      assert_includes Actions::Profile.each_submodel.to_a, registered
      context = Module.new
      made = context.profile('Made')
      assert_same context::Made, made
      assert_includes Actions::Profile.each_submodel.to_a, made
    end

    def test_definitions_are_named_as_written_and_answered_by_the_profile
      profile = Actions::Profile.new('Base')
      definition = profile.define('drive', @task)
      assert_kind_of Actions::Profile::Definition, definition
      assert_equal ['drive', profile], [definition.name, definition.profile]
      assert_same definition, profile.drive_def
      assert_equal 'Base.drive_def', definition.to_s
      assert_kind_of Actions::Profile::Definition, definition.with_arguments(x: 1)
      assert_equal %w[drive], profile.each_definition.map(&:name)
      assert_raises(ArgumentError) { profile.drive_def('x') }
      assert_raises(NoMethodError) { profile.other_def }
    end

    # The selections in effect for a definition's children: its own use,
    # and the profile's, as one injection.
    def test_resolved_dependency_injection_has_the_selections_in_effect
      @task.provides @pose, as: 'pose'
      cmp = Composition.new_submodel(name: 'Follow')
      cmp.add @pose, as: 'pose'
      assert_equal @task.pose_srv, cmp.use('pose' => @task.pose_srv).resolved_dependency_injection.explicit['pose']
      profile = Actions::Profile.new('Base')
      profile.use @pose => @task
      profile.define 'follow', cmp
      resolved = profile.resolved_definition('follow').resolved_dependency_injection
      assert_equal @task.pose_srv, resolved.explicit[@pose]
    end

    def test_definition_gives_a_new_copy_each_time
      profile = Actions::Profile.new
      profile.define('drive', @task)
      assert_equal profile.drive_def, profile.definition('drive')
      refute_same profile.definition('drive'), profile.definition('drive')
      refute_same profile.drive_def, profile.resolved_definition('drive')
      assert_raises(UnknownName) { profile.definition('fly') }
    end

    def test_tags_and_selections_of_a_profile_object
      profile = Actions::Profile.new
      tag = profile.tag('localization', @pose)
      assert_same tag, profile.localization_tag
      assert_equal 'anonymous profile.localization_tag', tag.to_s
      profile.use(@task => @task)
      assert_equal({ @task => @task }, profile.selections.explicit)
    end

    def test_tasks_of_a_tag_stand_for_that_tag_only
      require 'syskit/test/plan'
      profile = Actions::Profile.new
      profile.tag('localization', @pose)
      profile.tag('odometry', @pose)
      plan = Test::Plan.new
      first = profile.localization_tag.instanciate(plan)
      again = profile.localization_tag.instanciate(plan)
      other = profile.odometry_tag.instanciate(plan)
      assert first.fullfills?(@pose)
      assert first.can_merge?(again)
      refute first.can_merge?(other)
      refute other.can_merge?(first)
    end

    def test_devices_declared_on_the_robot_of_a_profile_object
      profile = Actions::Profile.new('Base')
      camera = Device.new_submodel(name: 'Camera')
      device = profile.robot.device(camera, as: 'front')
      assert_same device, profile.front_dev.device
      assert_raises(ArgumentError) { profile.front_dev('x') }
    end
  end
end
