# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Specializations, as Syskit selects them: the specializations that the
  # selected components fullfill apply together, unless a constraint
  # forbids it (then the choice is ambiguous, and prefer_specializations
  # decides).
  class TestSpecializations < Minitest::Test
    include CompositionTestHelper

    def setup
      super
      load_rig
      @model = Composition.new_submodel(name: 'Drive') do
        add Rig::Services::Pose, as: 'pose'
        add OroGen.rig.Follower, as: 'follow'
      end
    end

    # A composition providing odometry (from a child of its own).
    def odometry_source
      Composition.new_submodel do
        add Rig::Services::Odometry, as: 'src'
        export src_child.odometry_port
        provides Rig::Services::Odometry, as: 'odometry'
      end
    end

    def test_no_specialization_applies_to_a_plain_selection
      assert_same @model, @model.narrow('pose' => OroGen.rig.Tracker.front_pose_srv)
    end

    # A submodel declares none of its own: its parent's apply to it.
    def test_a_parents_specialization_applies_to_a_submodel
      submodel = @model.new_submodel
      refute submodel.specializations?
      @model.specialize @model.pose_child => Rig::Services::Odometry
      assert submodel.specializations?
      narrowed = submodel.narrow('pose' => odometry_source)
      assert narrowed.specialization?
      assert narrowed <= submodel
    end

    # As Syskit's: a component selected through one of its services
    # matches the specializations on that service only, whether the
    # service is selected for the child or for the model it requires.
    def test_a_selected_service_says_which_specialization_applies
      heading = DataService.new_submodel(name: 'Heading') { output_port 'heading', RBS }
      heading.provides Rig::Services::Pose, 'pose' => 'heading'
      task_m = TaskContext.new_submodel(name: 'Imu') do
        output_port 'odom', RBS
        output_port 'yaw', RBS
      end
      task_m.provides Rig::Services::Odometry, as: 'odometry', 'odometry' => 'odom'
      task_m.provides heading, as: 'heading', 'heading' => 'yaw'
      @model.add_specialization_constraint { |_, _| false }
      odometry = @model.specialize(@model.pose_child => Rig::Services::Odometry)
      @model.specialize(@model.pose_child => heading)
      assert_equal Set[odometry], @model.narrow('pose' => task_m.odometry_srv).applied_specializations
      by_model = DependencyInjection.new('pose' => task_m, Rig::Services::Pose => task_m.odometry_srv)
      assert_equal Set[odometry], @model.narrow(by_model).applied_specializations
    end

    def test_a_specialization_applies_when_the_selection_fullfills_it
      spec = @model.specialize @model.pose_child => Rig::Services::Odometry do
        pose_child.odometry_port.connect_to follow_child.pose_port
      end
      odometry = odometry_source
      narrowed = @model.narrow('pose' => odometry)
      assert narrowed < @model
      assert_equal Set[spec], narrowed.applied_specializations
      assert_equal 'Drive/pose.is_a?(Rig::Services::Odometry)', narrowed.name
      assert narrowed.pose_child.odometry_port.connected_to?(narrowed.follow_child.pose_port)
      refute_same narrowed, @model.narrow
      assert_same narrowed, @model.narrow('pose' => odometry)
    end

    def test_connections_of_a_specialization_stay_in_it
      spec = @model.specialize @model.pose_child => Rig::Services::Odometry do
        pose_child.odometry_port.connect_to follow_child.pose_port
      end
      assert_equal 1, spec.composition_model.port_connections.size
      assert_empty @model.port_connections
    end

    # The splitter, providing SpeedSource through its left output.
    def splitter_as_speed_source
      splitter = OroGen.rig.Splitter
      splitter.provides(Rig::Services::SpeedSource, as: 'left_speed', 'speed_out' => 'left') unless
        splitter.find_service('left_speed')
      splitter
    end

    def test_specializations_that_apply_together_are_merged
      @model.add(Rig::Services::SpeedSource, as: 'speed')
      odometry = @model.specialize(@model.pose_child => Rig::Services::Odometry) { export pose_child.odometry_port }
      speed = @model.specialize(@model.speed_child => OroGen.rig.Splitter) { export speed_child.left_port }
      narrowed = @model.narrow('pose' => odometry_source, 'speed' => splitter_as_speed_source)
      assert_equal Set[odometry, speed], narrowed.applied_specializations
      assert_equal %w[left odometry], narrowed.ports.keys.sort
      assert_equal %w[left odometry], narrowed.each_port.map(&:name).sort
    end

    def test_a_constraint_makes_two_specializations_ambiguous
      @model.add(Rig::Services::SpeedSource, as: 'speed')
      @model.add_specialization_constraint { |a, b| a == b }
      first = @model.specialize(@model.pose_child => Rig::Services::Odometry)
      @model.specialize(@model.pose_child => Composition)
      source = odometry_source
      error = assert_raises(NetworkError) { @model.narrow('pose' => source) }
      assert_match(/several specializations of Drive apply .* and cannot be combined/, error.message)
      assert_match(/prefer_specializations/, error.hint)
      narrowed = @model.narrow({ 'pose' => source }, hints: [{ 'pose' => Rig::Services::Odometry }])
      assert_equal Set[first], narrowed.applied_specializations
    end

    # As in Syskit, the constraints are asked when a specialization is
    # declared.
    def test_constraints_must_be_symmetric
      @model.add_specialization_constraint { |a, _b| a.specialized_children['pose'] == [Rig::Services::Odometry] }
      @model.specialize(@model.pose_child => Rig::Services::Odometry)
      error = assert_raises(DeclarationError) { @model.specialize(@model.pose_child => Composition) }
      assert_match(/not symmetric/, error.message)
    end

    def test_specializations_record_those_the_constraints_let_them_combine_with
      @model.add_specialization_constraint { |a, b| a.specialized_children.keys != b.specialized_children.keys }
      odometry = @model.specialize(@model.pose_child => Rig::Services::Odometry)
      follower = @model.specialize(@model.follow_child => OroGen.rig.Follower.new_submodel)
      tracker = @model.specialize(@model.pose_child => OroGen.rig.Tracker)
      assert_equal [follower].to_set, odometry.compatibilities
      assert_equal [odometry, tracker].to_set, follower.compatibilities
      assert odometry.compatible_with?(follower)
      refute odometry.compatible_with?(tracker)
    end

    def test_specialize_without_children_makes_a_private_submodel
      private_m = @model.specialize { add OroGen.rig.Splitter, as: 'split' }
      assert private_m.private_specialization?
      refute @model.private_specialization?
      assert_same @model, private_m.superclass
      assert_equal 'Drive{1}', private_m.name
      assert private_m.find_child('split')
      refute @model.find_child('split')
      assert OroGen.rig.Follower.specialize.private_specialization?
    end

    def test_two_specialized_models_merge_into_the_one_with_both_specializations
      odometry = @model.specialize(@model.pose_child => Rig::Services::Odometry)
      follower = @model.specialize(@model.follow_child => OroGen.rig.Follower.new_submodel)
      merged = odometry.composition_model.merge(follower.composition_model)
      assert_equal Set[odometry, follower], merged.applied_specializations
      assert_same merged, follower.composition_model.merge(odometry.composition_model)
      assert_same odometry.composition_model, odometry.composition_model.merge(@model)
    end

    def test_an_empty_specialization_is_compatible_with_any
      empty = Models::CompositionSpecialization.new
      assert empty.empty?
      assert empty.compatible_with?(Models::CompositionSpecialization.new('pose' => Rig::Services::Odometry))
    end

    def test_a_specialization_value_merges_others
      pose = Models::CompositionSpecialization.new('pose' => Rig::Services::Odometry)
      follow = Models::CompositionSpecialization.new('follow' => [OroGen.rig.Follower])
      shared = Object.new
      pose.compatibilities << shared << Object.new
      follow.compatibilities << shared
      follow.merge(pose)
      assert_equal [shared, pose].to_set, follow.compatibilities
      assert_equal({ 'follow' => [OroGen.rig.Follower], 'pose' => Rig::Services::Odometry },
                   follow.specialized_children)
      assert follow.weak_match?('pose' => [Rig::Services::Odometry], 'other' => OroGen.rig.Splitter)
      refute follow.weak_match?('pose' => Rig::Services::Pose)
    end

    def test_a_child_may_be_named_by_the_model_it_requires
      spec = @model.specialize(Rig::Services::Pose => Rig::Services::Odometry)
      assert_equal({ 'pose' => [Rig::Services::Odometry] }, spec.specialized_children)
      error = assert_raises(DeclarationError) { @model.specialize(Rig::Services::SpeedSource => OroGen.rig.Splitter) }
      assert_match(/no child of Drive requires Rig::Services::SpeedSource/, error.message)
      @model.add(Rig::Services::Pose, as: 'other')
      error = assert_raises(DeclarationError) { @model.specialize(Rig::Services::Pose => Rig::Services::Odometry) }
      assert_match(/several children of Drive require Rig::Services::Pose \(pose, other\)/, error.message)
      assert_match(/specialize pose_child =>/, error.hint)
    end

    def test_a_specialization_must_refine_the_child_with_models
      error = assert_raises(DeclarationError) { @model.specialize(@model.follow_child => OroGen.rig.Follower) }
      assert_match(/does not specialize Drive.follow_child: it already requires rig::Follower/, error.message)
      error = assert_raises(DeclarationError) { @model.specialize(@model.follow_child => OroGen.rig.Splitter) }
      assert_match(/cannot be both a rig::Follower and a rig::Splitter/, error.message)
      error = assert_raises(DeclarationError) { @model.specialize(@model.pose_child => 'Odometry') }
      assert_match(/specialize pose => "Odometry": not a task, composition or data service model/, error.message)
      error = assert_raises(DeclarationError) { @model.specialize(42 => Rig::Services::Odometry) }
      assert_match(/specialize cannot select a child with 42/, error.message)
      assert_empty @model.specializations
    end

    # As Syskit's specialization manager: a submodel has its parent's
    # specializations, found by what they specialize.
    def test_a_submodel_has_the_specializations_of_its_parent
      odometry = @model.specialize(@model.pose_child => Rig::Services::Odometry)
      submodel = @model.new_submodel
      assert_equal [{ 'pose' => [Rig::Services::Odometry] }], submodel.specializations.specializations.keys
      assert_equal @model.specializations.specializations.keys, submodel.specializations.specializations.keys
      refute_same odometry, submodel.specializations.first
      assert submodel.specializations.first.composition_model < submodel
    end

    # The block runs when the specialization is declared, so that a
    # mistake is reported at its line even if no network selects it.
    def test_a_specialization_block_is_checked_where_it_is_written
      error = assert_raises(DeclarationError) do
        @model.specialize(@model.pose_child => Rig::Services::Odometry) { pose_child.odometry_port.connect_to follow_child.command_port }
      end
      assert_equal File.expand_path(__FILE__), error.location.path
      assert_raises(NameError) do
        @model.specialize(@model.pose_child => Rig::Services::Odometry) { this_is_no_statement }
      end
    end

    def test_syskit_s_not_option_is_accepted_with_a_warning
      spec = @model.specialize(@model.pose_child => Rig::Services::Odometry, not: OroGen.rig.Tracker)
      assert_equal %w[pose], spec.specialized_children.keys
      assert_match(/specialize's not: option: not modelled/, Syskit.app.problems.last.message)
    end

    def test_find_specialization_answers_constraint_blocks
      spec = @model.specialize(@model.pose_child => Rig::Services::Odometry)
      assert_equal [Rig::Services::Odometry], spec.find_specialization('pose', Rig::Services::Pose)
      assert_nil spec.find_specialization('follow', Rig::Services::Pose)
      assert spec.has_specialization?('pose', Rig::Services::Odometry)
    end

    def test_specializing_an_unknown_child
      error = assert_raises(DeclarationError) { @model.specialize('poses' => Rig::Services::Odometry) }
      assert_match(/specialize names poses, which is not a child of Drive \(did you mean 'pose'\?\)/, error.message)
    end

    def test_submodels_inherit_specializations
      spec = @model.specialize(@model.pose_child => Rig::Services::Odometry) { export pose_child.odometry_port }
      submodel = @model.new_submodel(name: 'SubDrive')
      source = odometry_source
      narrowed = submodel.narrow('pose' => source)
      assert narrowed < submodel
      assert_equal spec.specialized_children, narrowed.applied_specializations.first.specialized_children
    end

    # The block sees the child as the specialization requires it, even
    # where a submodel made the child a component that provides it.
    def test_a_specialization_block_sees_the_child_as_the_specialized_model
      @model.specialize(@model.pose_child => Rig::Services::Odometry) { export pose_child.odometry_port, as: 'odo' }
      source = odometry_source
      submodel = @model.new_submodel(name: 'SourcedDrive')
      submodel.overload 'pose', source
      narrowed = submodel.narrow
      refute_same submodel, narrowed
      assert_equal %w[odo], narrowed.ports.keys
      assert_equal narrowed.pose_child.odometry_port, narrowed.find_exported_output('odo')
    end

    # A model with more specializations of the same root fullfills one
    # with fewer, and a submodel of a specialized model has its
    # specializations.
    def test_specialized_models_fullfill_those_with_fewer_specializations
      @model.add(Rig::Services::Pose, as: 'other')
      @model.specialize(@model.pose_child => Rig::Services::Odometry)
      @model.specialize(@model.other_child => Rig::Services::Odometry)
      source = odometry_source
      one = @model.narrow('pose' => source)
      both = @model.narrow('pose' => source, 'other' => source)
      assert both.fullfills?(one)
      assert both.new_submodel.fullfills?(one)
      refute one.fullfills?(both)
      refute @model.fullfills?(one)
      assert_equal both.applied_specializations, both.new_submodel.applied_specializations
    end

    def test_narrow_model_of_requirements
      @model.specialize(@model.pose_child => Rig::Services::Odometry)
      source = odometry_source
      assert @model.use('pose' => source).narrow_model < @model
      assert_same @model, @model.use('pose' => OroGen.rig.Tracker.front_pose_srv).narrow_model
    end
  end
end
