# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'syskit/test/plan'

module Syskit
  # Syskit's model-level +instanciate+: a composition model (or
  # requirements) made into tasks in a plan held as data, its children
  # chosen through a DependencyInjectionContext, what stays abstract a
  # placeholder task.
  class TestModelInstanciate < Minitest::Test
    include CompositionTestHelper

    def setup
      super
      load_rig
      @plan = Test::Plan.new
    end

    def watch_model
      Composition.new_submodel do
        add Rig::Services::Pose, as: 'pose'
        add OroGen.rig.Follower, as: 'follower'
      end
    end

    def test_a_composition_model_instanciates_its_children_into_the_plan
      context = DependencyInjectionContext.new(Rig::Services::Pose => OroGen.rig.Tracker.front_pose_srv)
      cmp = watch_model.instanciate(@plan, context)
      assert_kind_of OroGen.rig.Tracker, cmp.pose_child
      assert_kind_of OroGen.rig.Follower, cmp.follower_child
      assert_equal [cmp, cmp.pose_child, cmp.follower_child].to_set, @plan.tasks
    end

    def test_selections_by_child_name_through_a_context
      context = DependencyInjectionContext.new('pose' => OroGen.rig.Tracker.front_pose_srv)
      cmp = watch_model.to_instance_requirements.instanciate(@plan, context)
      assert_kind_of OroGen.rig.Tracker, cmp.pose_child
    end

    def test_a_context_is_made_of_injection_layers_later_ones_winning
      first = DependencyInjection.new('pose' => OroGen.rig.Tracker.front_pose_srv)
      context = DependencyInjectionContext.new(first, 'pose' => DependencyInjection.nothing)
      cmp = watch_model.instanciate(@plan, context)
      assert_kind_of Rig::Services::Pose.placeholder_model, cmp.pose_child
    end

    def test_what_nothing_selects_is_a_task_of_the_placeholder_model
      cmp = watch_model.instanciate(@plan)
      assert_kind_of Rig::Services::Pose.placeholder_model, cmp.pose_child
      assert cmp.pose_child.model.placeholder?
    end

    # provides includes the service's module: a task of a model providing
    # it, a driver or a placeholder standing for the service, is one.
    def test_a_task_providing_a_service_is_kind_of_it
      assert_kind_of Rig::Services::Pose, watch_model.instanciate(@plan).pose_child
      driver = OroGen.rig.GPSDriver.new
      assert_kind_of Rig::Devices::GPS, driver
      assert_kind_of Rig::Services::Pose, driver
      refute_kind_of Rig::Services::Pose, OroGen.rig.Follower.new
    end

    def test_a_data_service_selected_for_a_child_adds_to_what_it_requires
      cmp = watch_model.instanciate(@plan, DependencyInjectionContext.new('pose' => Rig::Services::SpeedSource))
      assert_equal [Rig::Services::SpeedSource, Rig::Services::Pose], cmp.pose_child.model.proxied_data_service_models
      cmp = watch_model.instanciate(@plan, DependencyInjectionContext.new('pose' => Rig::Services::SpeedSource.placeholder_model))
      assert_equal [Rig::Services::SpeedSource, Rig::Services::Pose].to_set,
                   cmp.pose_child.model.proxied_data_service_models.to_set
      refined = InstanceRequirements.new([Rig::Services::Pose]).add_models([Rig::Services::Odometry])
      assert_equal [Rig::Services::Odometry], refined.models
    end

    def test_task_arguments_are_the_root_task_arguments
      model = watch_model
      model.argument :gain
      cmp = model.instanciate(@plan, task_arguments: { gain: 3 })
      assert_equal 3, cmp.arguments[:gain]
    end

    def test_a_task_model_instanciates_into_one_task
      task = OroGen.rig.Follower.instanciate(@plan)
      assert_kind_of OroGen.rig.Follower, task
      assert_equal [task].to_set, @plan.tasks
    end

    def test_a_task_has_its_services_as_readers
      task = OroGen.rig.Tracker.new
      assert_equal BoundDataService.new(task, OroGen.rig.Tracker.front_pose_srv), task.front_pose_srv
      assert_equal %w[front_pose rear_pose], task.each_data_service.map(&:name).sort
    end

    def test_the_required_child_is_the_selected_service_of_the_task
      context = DependencyInjectionContext.new('pose' => OroGen.rig.Tracker.rear_pose_srv)
      cmp = watch_model.instanciate(@plan, context)
      assert_equal cmp.pose_child.rear_pose_srv, cmp.required_composition_child_from_role('pose')
      assert_same cmp.follower_child, cmp.required_composition_child_from_role('follower')
    end

    def test_a_composition_keeps_what_was_selected_for_each_child
      rear = OroGen.rig.Tracker.rear_pose_srv
      cmp = watch_model.instanciate(@plan, DependencyInjectionContext.new('pose' => rear))
      selection = cmp.child_selection['pose']
      assert_same cmp.pose_child, selection.component
      assert_equal({ Rig::Services::Pose => rear }, selection.service_selection)
      assert_equal({ 'pose' => 'rear' }, selection.port_mappings)
      assert_equal [Rig::Services::Pose], selection.required.models
    end

    def test_children_selections_from_a_context_by_child_name
      model = watch_model
      explicit, all, used = model.find_children_models_and_tasks('pose' => OroGen.rig.Tracker.front_pose_srv)
      assert_equal %w[pose], explicit.keys
      assert_equal %w[follower pose], all.keys.sort
      assert_equal({ 'pose' => 'front' }, explicit['pose'].port_mappings)
      assert_equal [OroGen.rig.Follower], all['follower'].selected.models
      assert_equal({ 'pose' => ['pose'], 'follower' => [] }, used.transform_values(&:to_a))
    end

    def test_a_composition_has_readers_of_its_exported_ports
      model = watch_model
      model.export model.follower_child.command_port
      cmp = model.instanciate(@plan, DependencyInjectionContext.new('pose' => OroGen.rig.Tracker.rear_pose_srv))
      # As in Syskit: the composition's own port, whose actual port is the
      # child's it is exported from.
      assert_same cmp, cmp.command_port.component
      assert_equal cmp.follower_child.command_port, cmp.command_port.to_actual_port
    end

    # A connection to a composition's port is one to the port of the child
    # task it exports.
    def test_a_composition_port_connects_the_port_it_exports
      model = watch_model
      model.export model.follower_child.command_port
      cmp = model.instanciate(@plan, DependencyInjectionContext.new('pose' => OroGen.rig.Tracker.rear_pose_srv))
      splitter = OroGen.rig.Splitter.new
      cmp.command_port.connect_to splitter.in_port
      assert cmp.follower_child.command_port.connected_to?(splitter.in_port)
      assert cmp.command_port.connected_to?(splitter.in_port)
    end

    # Roby's +Model.as_plan+: a task to be planned, holding the model's
    # requirements.
    def test_a_component_model_as_plan_is_a_task_to_be_planned
      task = OroGen.rig.Follower.as_plan(speed: 2)
      assert_kind_of OroGen.rig.Follower, task
      assert_equal({ speed: 2 }, task.arguments.each_assigned_argument.to_h)
      assert_equal OroGen.rig.Follower.with_arguments(speed: 2), task.planning_task.requirements
    end

    # As Roby's plan.replace: the new task takes the child's roles, and
    # the composition's connections map onto its ports.
    def test_a_child_replaced_in_the_plan_takes_its_connections
      model = watch_model
      model.pose_child.pose_port.connect_to model.follower_child.pose_port
      cmp = model.instanciate(@plan)
      placeholder = cmp.pose_child
      sink = cmp.follower_child.pose_port
      assert placeholder.pose_port.connected_to?(sink)
      gps = @plan.replace(placeholder, OroGen.rig.GPSDriver.new)
      assert_equal [gps, true, false], [cmp.pose_child, sink.connected_to?(gps.position_port),
                                        placeholder.pose_port.connected_to?(sink)]
      assert @plan.include?(placeholder)
    end

    def test_a_task_replaced_leaves_the_plan
      cmp = watch_model.instanciate(@plan)
      placeholder = cmp.pose_child
      gps = @plan.replace_task(placeholder, OroGen.rig.GPSDriver.new)
      assert_same gps, cmp.pose_child
      refute @plan.include?(placeholder)
    end

    # As Syskit's: requirements with a service selected instanciate into
    # that service of the task; a placeholder's service may be selected
    # on requirements of its service models.
    def test_requirements_on_a_service_instanciate_into_the_service_of_the_task
      bound = OroGen.rig.Tracker.rear_pose_srv.to_instance_requirements.instanciate(@plan)
      assert_equal [OroGen.rig.Tracker.rear_pose_srv, OroGen.rig.Tracker], [bound.model, bound.component.model]
      placeholder_srv = Rig::Services::Pose.placeholder_model.find_data_service_from_type(Rig::Services::Pose)
      requirements = InstanceRequirements.new([Rig::Services::Pose]).select_service(placeholder_srv)
      assert_equal placeholder_srv, requirements.service
      assert_equal placeholder_srv, requirements.instanciate(@plan).model
    end

    def test_a_child_removed_from_the_task_is_no_required_child
      cmp = watch_model.instanciate(@plan, DependencyInjectionContext.new('pose' => OroGen.rig.Tracker.rear_pose_srv))
      cmp.remove_dependency(cmp.pose_child)
      assert_nil cmp.find_required_composition_child_from_role('pose')
      assert_raises(ArgumentError) { cmp.required_composition_child_from_role('pose') }
      task = OroGen.rig.Tracker.new
      cmp.depends_on(task, role: 'pose')
      assert_same task, cmp.pose_child
    end

    def test_a_service_may_be_named_after_an_anonymous_model
      srv = DataService.new_submodel
      task_m = TaskContext.new_submodel { provides srv, as: srv.to_s }
      assert_same srv, task_m.find_service(srv.to_s).model
      error = assert_raises(DeclarationError) { TaskContext.new_submodel { provides srv, as: 'a.b' } }
      assert_match(/'a.b' is not a valid service name/, error.message)
    end
  end
end
