# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'syskit/test/plan'

module Syskit
  # A composition model's child and the tasks of a plan standing for it,
  # as Syskit's CompositionChild binds them; and the model registry and
  # plain component models Syskit's tests build them with.
  class TestChildBinding < Minitest::Test
    include CompositionTestHelper

    def setup
      super
      load_rig
      @plan = Test::Plan.new
      @inner = Composition.new_submodel(name: 'Inner') { add Rig::Services::Pose, as: 'pose' }
      inner = @inner
      @outer = Composition.new_submodel(name: 'Outer') { add inner, as: 'inner' }
    end

    def outer_task
      context = DependencyInjectionContext.new('inner.pose' => OroGen.rig.Tracker.rear_pose_srv)
      @outer.instanciate(@plan, context)
    end

    def test_a_child_resolves_to_the_service_selected_for_it
      cmp = outer_task
      tracker = cmp.inner_child.pose_child
      assert_equal tracker.rear_pose_srv, @inner.pose_child.try_resolve_and_bind_child(cmp.inner_child)
      assert_equal tracker.rear_pose_srv, @outer.inner_child.pose_child.try_resolve_and_bind_child_recursive(cmp)
      assert_same cmp.inner_child, @outer.inner_child.resolve_and_bind_child(cmp)
      cmp.remove_child(cmp.inner_child)
      assert_nil @outer.inner_child.pose_child.try_resolve_and_bind_child_recursive(cmp)
      assert_raises(ArgumentError) { @outer.inner_child.pose_child.resolve_and_bind_child_recursive(cmp) }
    end

    def test_a_task_binds_to_the_child_it_is
      cmp = outer_task
      tracker = cmp.inner_child.pose_child
      assert_equal [cmp.inner_child], tracker.each_parent_task.to_a
      assert_equal tracker.rear_pose_srv, @inner.pose_child.bind(tracker)
      assert_equal tracker.front_pose_srv, @inner.pose_child.bind(tracker.front_pose_srv)
      error = assert_raises(ArgumentError) { @outer.inner_child.bind(tracker) }
      assert_match(/to rig::Tracker:0x\h+: it is not the child of any Outer composition/, error.message)
    end

    def test_a_task_of_another_role_does_not_bind
      other = @inner.new
      other.depends_on(OroGen.rig.Tracker.new, role: 'pose')
      loose = OroGen.rig.Tracker.new
      other.depends_on(loose, role: 'spare')
      error = assert_raises(ArgumentError) { @inner.pose_child.bind(loose) }
      assert_match(/but not with the role 'pose'/, error.message)
      beat = DataService.new_submodel(name: 'Beat')
      source = Component.new_submodel(name: 'Src') { provides beat, as: 'beat' }.new
      error = assert_raises(ArgumentError) { @inner.pose_child.bind(source.beat_srv) }
      assert_match(/cannot bind .* to #<BoundDataService: Src:0x\h+\.beat>/, error.message)
    end

    def test_a_child_added_later_is_readable_through_a_parent_child
      reached = @outer.inner_child
      @inner.add OroGen.rig.Follower, as: 'late'
      assert_equal 'late', reached.late_child.child_name
    end

    def test_component_models_register_their_submodels
      sub = @inner.new_submodel
      assert Component.has_submodel?(@inner)
      assert Composition.has_submodel?(sub)
      assert @inner.has_submodel?(sub)
      @inner.clear_submodels
      refute @inner.has_submodel?(sub)
      refute Component.has_submodel?(sub)
      assert Component.has_submodel?(@inner)
    end

    def test_a_plain_component_model_provides_services_and_instantiates
      srv = DataService.new_submodel(name: 'Heartbeat')
      model = Component.new_submodel(name: 'Source') { provides srv, as: 'pose' }
      assert_equal 'Source', model.name
      refute model.abstract?
      @inner.add srv, as: 'beat'
      cmp = @inner.instanciate(@plan, DependencyInjectionContext.new('beat' => model))
      assert_kind_of model, cmp.beat_child
      assert_equal model.pose_srv.bind(cmp.beat_child), @inner.beat_child.try_resolve_and_bind_child(cmp)
    end

    def test_ports_bind_to_the_ports_of_the_tasks
      @inner.export @inner.pose_child.pose_port, as: 'where'
      cmp = @inner.instanciate(@plan, DependencyInjectionContext.new('pose' => OroGen.rig.Tracker.rear_pose_srv))
      tracker = cmp.pose_child
      assert_equal tracker.rear_port, @inner.where_port.bind(cmp).to_actual_port
      gps = OroGen.rig.GPSDriver.new
      assert_equal gps.position_port, @inner.pose_child.pose_port.bind(gps)
      assert_raises(ArgumentError) { @inner.pose_child.pose_port.bind(OroGen.rig.Follower.new) }
    end

    def test_a_composition_task_has_the_ports_it_exports
      @inner.export @inner.pose_child.pose_port, as: 'where'
      cmp = @inner.instanciate(@plan, DependencyInjectionContext.new('pose' => OroGen.rig.Tracker.rear_pose_srv))
      assert_same cmp, cmp.where_port.component
      assert_equal @inner.where_port, cmp.where_port.model
      assert_equal cmp.pose_child.rear_port, cmp.where_port.to_actual_port
    end
  end
end
