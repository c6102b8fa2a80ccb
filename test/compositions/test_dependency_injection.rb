# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Dependency injection as Syskit resolves it: by name before by model,
  # defaults only where they are not ambiguous, a selection not applied
  # again inside what it selected, grandchildren by dotted names.
  class TestDependencyInjection < Minitest::Test
    include CompositionTestHelper

    def setup
      super
      load_rig
      @watch = Composition.new_submodel(name: 'Watch') do
        add Rig::Services::Pose, as: 'pose'
        add OroGen.rig.Follower, as: 'follower'
        pose_child.pose_port.connect_to follower_child.pose_port
      end
    end

    def context(*mappings)
      DependencyInjection::Context::EMPTY.with(DependencyInjection::EMPTY.add(mappings, nil))
    end

    def selected(context, child = @watch.pose_child)
      Network::Selection.select(child, context).requirements
    end

    def test_a_selection_by_name_wins_over_one_by_model
      front = OroGen.rig.Tracker.front_pose_srv
      rear = OroGen.rig.Tracker.rear_pose_srv
      result = selected(context({ 'pose' => front, Rig::Services::Pose => rear }))
      assert_same front, result.service
    end

    def test_a_default_selects_every_model_it_fullfills_unless_two_defaults_do
      assert_same OroGen.rig.Tracker.rear_pose_srv, selected(context(OroGen.rig.Tracker.rear_pose_srv)).service
      odometry = Composition.new_submodel do
        add Rig::Services::Odometry, as: 'src'
        export src_child.odometry_port
        provides Rig::Services::Odometry, as: 'odometry'
      end
      ambiguous = context(odometry, OroGen.rig.Tracker.front_pose_srv)
      assert_equal [Rig::Services::Pose], selected(ambiguous).models
      assert selected(ambiguous).abstract?
    end

    def test_nothing_keeps_the_child_s_own_model
      result = selected(context({ 'pose' => DependencyInjection.nothing, Rig::Services::Pose => OroGen.rig.Tracker }))
      assert_equal [Rig::Services::Pose], result.models
    end

    def test_a_selection_does_not_apply_again_inside_what_it_selected
      nested = Composition.new_submodel(name: 'Nested') do
        add Rig::Services::Pose, as: 'pose'
        export pose_child.pose_port
        provides Rig::Services::Pose, as: 'pose_out'
      end
      ctx = context({ Rig::Services::Pose => nested })
      _, used = ctx.selection_for('pose', [Rig::Services::Pose])
      inner = ctx.mask(used)
      assert_nil inner.selection_for('pose', [Rig::Services::Pose]).first
    end

    def test_grandchildren_are_selected_by_dotted_names
      injection = DependencyInjection::EMPTY.add([{ 'watch.pose' => OroGen.rig.Tracker, 'other' => @watch }], nil)
      assert_equal({ 'pose' => OroGen.rig.Tracker }, injection.grandchild_selections('watch'))
    end

    def test_keys_are_child_names_or_models
      error = assert_raises(DeclarationError) { DependencyInjection::EMPTY.add([{ 42 => OroGen.rig.Tracker }], nil) }
      assert_match(/use cannot select for 42: keys are child names or models/, error.message)
    end

    # As in Syskit, +use+ checks that its names are children (the first
    # part of a dotted name; a child a specialization adds counts).
    def test_use_names_children_of_the_composition
      error = assert_raises(DeclarationError) { @watch.use('pos' => OroGen.rig.Tracker) }
      assert_equal "pos is not a child of Watch (did you mean 'pose'?)", error.message
      assert_equal 'its children: pose, follower', error.hint
      assert_equal File.expand_path(__FILE__), error.location.path
      error = assert_raises(DeclarationError) { @watch.use('folower.pose' => OroGen.rig.Tracker) }
      assert_match(/\Afolower is not a child of Watch \(did you mean 'follower'\?\) \(in use\('folower.pose'/,
                   error.message)
      @watch.specialize(@watch.pose_child => Rig::Services::Odometry) { add OroGen.rig.Logger, as: 'log' }
      assert @watch.use('log' => OroGen.rig.Logger, 'pose.x' => OroGen.rig.Tracker)
    end

    def test_chains_of_selections_are_followed
      with_gain = OroGen.rig.Follower.with_arguments(gain: 3.0)
      ctx = context({ Rig::Services::Pose => OroGen.rig.Tracker.front_pose_srv, OroGen.rig.Follower => with_gain })
      assert_same with_gain, ctx.direct_selection_for(OroGen.rig.Follower)
      assert_equal({ gain: 3.0 }, selected(ctx, @watch.follower_child).arguments)
    end
  end
end
