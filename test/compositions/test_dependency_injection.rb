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
      DependencyInjectionContext::EMPTY.with(DependencyInjection.new(*mappings))
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
      result = selected(context({ 'pose' => DependencyInjection.nothing,
                                  Rig::Services::Pose => OroGen.rig.Tracker.front_pose_srv }))
      assert_equal [Rig::Services::Pose], result.models
    end

    # As Syskit's: a component selected for a service it provides twice
    # does not say which one.
    def test_a_component_providing_a_service_twice_is_ambiguous_for_it
      assert_raises(AmbiguousServiceSelection) { context({ Rig::Services::Pose => OroGen.rig.Tracker }) }
    end

    def test_a_selection_does_not_apply_again_inside_what_it_selected
      nested = Composition.new_submodel(name: 'Nested') do
        add Rig::Services::Pose, as: 'pose'
        export pose_child.pose_port
        provides Rig::Services::Pose, as: 'pose_out'
      end
      ctx = context({ Rig::Services::Pose => nested })
      _, used = ctx.selected_value_for('pose', [Rig::Services::Pose])
      inner = ctx.mask(used)
      assert_nil inner.selected_value_for('pose', [Rig::Services::Pose]).first
    end

    def test_an_instance_selection_says_what_fills_a_requirement
      rear = OroGen.rig.Tracker.rear_pose_srv
      selection, used = DependencyInjection.new({ 'pose' => rear }).instance_selection_for('pose', Rig::Services::Pose)
      assert_equal ['pose'], used.to_a
      assert_equal({ Rig::Services::Pose => rear }, selection.service_selection)
      abstract = DependencyInjection.new({ 'pose' => OroGen.rig.Tracker.to_instance_requirements.abstract })
      assert abstract.instance_selection_for('pose', OroGen.rig.Tracker).first.selected.abstract?
    end

    def test_grandchildren_are_selected_by_dotted_names
      injection = DependencyInjection.new({ 'watch.pose' => OroGen.rig.Tracker, 'other' => @watch })
      assert_equal({ 'pose' => OroGen.rig.Tracker }, injection.grandchild_selections('watch'))
    end

    def test_keys_are_child_names_or_models
      error = assert_raises(DeclarationError) { DependencyInjection.new({ 42 => OroGen.rig.Tracker }) }
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

    # As Syskit's layers: a default of an inner layer (a model selecting
    # itself) does not undo what an outer one selected for that model.
    def test_a_default_does_not_undo_an_outer_selection_of_its_model
      front = OroGen.rig.Tracker.front_pose_srv
      layered = DependencyInjectionContext::EMPTY
                .with(DependencyInjection.new({ Rig::Services::Pose => front }))
                .with(DependencyInjection.new(Rig::Services::Pose, { 'name' => Rig::Services::Pose }))
      assert_same front, layered.direct_selection_for(Rig::Services::Pose)
      assert_same front, layered.state['name']
    end

    def test_do_not_inherit_falls_back_to_the_selection_by_model
      rear = OroGen.rig.Tracker.rear_pose_srv
      outer = context({ 'pose' => OroGen.rig.Tracker.front_pose_srv, Rig::Services::Pose => rear })
      inner = outer.with(DependencyInjection.new({ 'pose' => DependencyInjection.do_not_inherit }))
      assert_same rear, selected(inner).service
    end

    def test_what_is_selected_for_a_model_must_be_that_model
      assert_syskit_error(/use cannot select rig::Follower for rig::Tracker: it is not a rig::Tracker/,
                          hint: /select rig::Tracker itself, or a submodel of it/) do
        @watch.use(OroGen.rig.Tracker => OroGen.rig.Follower)
      end
      assert_syskit_error(/use cannot select Rig::Services::Pose for rig::Tracker/) do
        @watch.use(OroGen.rig.Tracker => Rig::Services::Pose)
      end
      assert_syskit_error(/use cannot select Rig::Services::SpeedCommand for Rig::Services::Pose/,
                          hint: /or a data service that provides it/) do
        @watch.use(Rig::Services::Pose => Rig::Services::SpeedCommand)
      end
      assert @watch.use(Rig::Services::Pose => Rig::Services::Odometry, OroGen.rig.Tracker => OroGen.rig.Tracker)
    end

    def test_use_is_for_compositions
      error = assert_syskit_error(/use selects children of compositions, and rig::Tracker.with_conf\("fast"\)/) do
        OroGen.rig.Tracker.with_conf('fast').use('x' => OroGen.rig.Follower)
      end
      assert_equal File.expand_path(__FILE__), error.location.path
    end
  end
end
