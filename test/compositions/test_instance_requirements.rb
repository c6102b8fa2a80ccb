# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'syskit/test/plan'

module Syskit
  # Requirements as Syskit's InstanceRequirements read and change: their
  # services and children (x_srv, x_child) and the statements that say
  # what is asked of them.
  class TestInstanceRequirements < Minitest::Test
    include CompositionTestHelper

    def tracker_app
      load_rig({ 'models/compositions/watch.rb' => WATCH }, profile: <<~RUBY, requires: ['models/compositions/watch'])
        profile 'Base' do
          define 'tracker', OroGen.rig.Tracker.with_arguments(rate: 5)
          define 'watch', Compositions::Watch.use('pose' => tracker_def.rear_pose_srv)
        end
      RUBY
    end

    def test_a_service_of_requirements_keeps_what_they_ask
      app = tracker_app
      rear = Rig::Profiles::Base.tracker_def.rear_pose_srv
      assert_same OroGen.rig.Tracker.rear_pose_srv, rear.service
      assert_equal({ rate: 5 }, rear.arguments)
      assert_equal 'Rig::Profiles::Base.tracker_def.rear_pose_srv', rear.to_s
      assert_same rear.service, OroGen.rig.Tracker.with_conf('fast').find_data_service('rear_pose').service
      assert_nil OroGen.rig.Tracker.with_conf('fast').find_data_service('side')
      assert_equal ['tracker.rear -> follower.pose'], connection_lines(plan_of(app, 'watch_def'))
    end

    # As Syskit's, a child reached from requirements has them as its
    # composition model; it is the composition's child otherwise.
    def test_the_children_of_requirements
      tracker_app
      watch = Rig::Profiles::Base.watch_def
      child = watch.pose_child
      assert_same watch, child.composition_model
      assert_equal 'pose', child.child_name
      assert_same Rig::Compositions::Watch.pose_child.requirements, child.requirements
      assert_equal child, watch.find_child('pose')
      refute_equal Rig::Compositions::Watch.pose_child, child
      assert_same Rig::Compositions::Watch, Rig::Compositions::Watch.pose_child.composition_model
      assert_equal child, child.pose_port.component_model
      refute_respond_to Rig::Profiles::Base.tracker_def, :pose_child
    end

    def test_a_service_by_its_model
      tracker_app
      follower = OroGen.rig.Follower.with_arguments(gain: 2)
      assert_nil follower.find_data_service_from_type(Rig::Services::Pose)
      rear = Rig::Profiles::Base.tracker_def.rear_pose_srv
      assert_same rear, rear.find_data_service_from_type(Rig::Services::Pose)
      error = assert_raises(AmbiguousServiceSelection) do
        Rig::Profiles::Base.tracker_def.find_data_service_from_type(Rig::Services::Pose)
      end
      assert_match(/several services of type Rig::Services::Pose: front_pose, rear_pose/, error.message)
      assert_equal File.expand_path(__FILE__), error.location.path
    end

    def test_a_misspelled_service_is_explained
      root = rig_app({ 'models/compositions/watch.rb' => WATCH },
                     profile: <<~RUBY, requires: ['models/compositions/watch'])
                       profile 'Base' do
                         define 'watch', Compositions::Watch.use('pose' => OroGen.rig.Tracker.with_arguments(rate: 5).rer_pose_srv)
                       end
                     RUBY
      error = load_problem(root)
      assert_match(/rig::Tracker.with_arguments\(rate: 5\) has no service 'rer_pose' \(did you mean 'rear_pose'\?\)/,
                   error.message)
      assert_equal 'its services: front_pose, rear_pose', error.hint
      assert_equal 'models/profiles/base.rb:7', error.location.to_s(root)
    end

    def test_statements_on_arguments_sections_and_services
      tracker_app
      follower = OroGen.rig.Follower.with_arguments(gain: 2.0)
      assert_empty follower.with_no_arguments.arguments
      assert_equal %w[fast], follower.use_conf('fast').conf
      rear = OroGen.rig.Tracker.with_conf('fast').select_service(OroGen.rig.Tracker.rear_pose_srv)
      assert_same OroGen.rig.Tracker.rear_pose_srv, rear.service
      assert_equal %w[fast], rear.conf
      assert_syskit_error(/service 'rear_pose' \(Rig::Services::Pose\) of rig::Tracker is not a service of/) do
        follower.select_service(OroGen.rig.Tracker.rear_pose_srv)
      end
    end

    # Syskit's deployment groups: a definition's tasks are deployed from
    # its requirements' deployments (or a named group's) before the robot's.
    def test_definitions_are_deployed_from_their_deployment_groups
      app = load_rig({ 'models/compositions/watch.rb' => WATCH },
                     profile: <<~RUBY, requires: ['models/compositions/watch'])
                       profile 'Base' do
                         define_deployment_group 'trackers' do
                           use_deployment OroGen.rig.Tracker => 'group_tracker'
                         end
                         define 'tracker', OroGen.rig.Tracker.use_deployment(OroGen.rig.Tracker => 'own_tracker')
                         define 'grouped', OroGen.rig.Tracker.use_deployment_group(trackers_deployment_group)
                       end
                     RUBY
      assert_empty app.problems
      assert_equal %w[own_tracker], plan_of(app, 'tracker_def').tasks.map(&:name)
      assert_equal %w[group_tracker], plan_of(app, 'grouped_def').tasks.map(&:name)
    end

    # As Syskit's requirements: marked abstract on request, equal when they
    # ask for the same thing, their model a placeholder when they name
    # services only; a service found by type is ambiguous when a required
    # service model provides it too.
    def test_requirements_made_in_ruby
      pose = DataService.new_submodel(name: 'Pose')
      task = Component.new_submodel { provides pose, as: 'fix' }
      assert task.to_instance_requirements.abstract.abstract?
      refute task.to_instance_requirements.abstract?
      assert_equal InstanceRequirements.new([task]), task.to_instance_requirements
      refute_equal task.to_instance_requirements, task.with_arguments(x: 1)
      assert_equal pose.placeholder_model, pose.to_instance_requirements.model
      assert_same task, InstanceRequirements.new([task]).model
      assert_equal task.fix_srv, task.new.fix_srv.model
    end

    def test_a_service_both_required_and_provided_is_ambiguous
      pose = DataService.new_submodel(name: 'Pose')
      odometry = DataService.new_submodel(name: 'Odometry') { provides pose }
      task = Component.new_submodel { provides pose, as: 'fix' }
      assert_equal [], InstanceRequirements.new.models
      assert_raises(AmbiguousServiceSelection) do
        InstanceRequirements.new([task, odometry]).find_data_service_from_type(pose)
      end
    end

    # Syskit's requirements made on a service (+new([Task.x_srv])+) and
    # their ports (x_port, of the selected service when there is one):
    # ports of the requirements, named as the service names them, standing
    # for the task's ports.
    def test_requirements_on_a_service_and_their_ports
      pose, task = pose_and_task
      on_service = InstanceRequirements.new([task.fix_srv])
      assert_equal [[task], task.fix_srv], [on_service.models, on_service.service]
      assert_equal %w[pose out], [on_service.pose_port.name, on_service.pose_port.to_component_port.name]
      assert_equal 'out', task.to_instance_requirements.out_port.name
      assert_nil on_service.find_port('nothing')
      summary = task.with_arguments(a: 1).fullfilled_model
      assert_equal [task, [pose, AbstractComponent, DataService], { a: 1 }],
                   [summary[0], summary[1].sort_by(&:to_s), summary[2]]
    end

    def test_the_ports_of_requirements_are_theirs
      _, task = pose_and_task
      on_service = InstanceRequirements.new([task.fix_srv])
      assert_same on_service, on_service.pose_port.component_model
      assert_equal Models::OutputPort.new(on_service, task.out_port.orogen_model, 'pose'), on_service.pose_port
      assert_equal on_service.to_component_model.out_port, on_service.pose_port.to_component_port
    end

    # Syskit's add_port_period: how often a port gets data, kept with the
    # requirements (and what they are merged with).
    def test_port_periods_are_kept_with_the_requirements
      _, task = pose_and_task
      requirements = task.to_instance_requirements.add_port_period('out', 0.1).add_port_period(:out, 0.5, 2)
      trigger = NetworkGeneration::PortDynamics::Trigger
      assert_equal [trigger.new('period', 0.1, 1), trigger.new('period', 0.5, 2)],
                   requirements.find_port_dynamics('out').triggers.to_a
      assert_nil task.to_instance_requirements.find_port_dynamics('out')
      assert_equal requirements.find_port_dynamics('out'),
                   task.to_instance_requirements.merge(requirements).find_port_dynamics('out')
      refute_equal requirements, task.to_instance_requirements
    end

    # Merging two requirements, binding a task to requirements.
    def test_merge_and_bind
      pose, task = pose_and_task
      on_service = InstanceRequirements.new([task.fix_srv])
      merged = task.with_arguments(a: 1).merge(on_service.abstract)
      assert_equal [task.fix_srv, { a: 1 }, false], [merged.service, merged.arguments, merged.abstract?]
      assert task.to_instance_requirements.abstract.merge(on_service, keep_abstract: true).abstract?
      assert_raises(IncompatibleComponentModels) { on_service.merge(TaskContext.new_submodel) }
      instance = task.new
      assert_same instance, pose.to_instance_requirements.try_bind(instance)
      assert_nil on_service.try_bind(TaskContext.new_submodel.new)
      assert_raises(ArgumentError) { on_service.bind(task) }
    end

    # Requirements as an action of Syskit's action interface: the model it
    # returns, an argument per task argument (required without default).
    def test_requirements_as_an_action_model
      _, task = pose_and_task
      task.argument :speed, doc: 'in m/s'
      task.argument :mode, default: 'fast'
      action = task.with_arguments(mode: 'slow').to_action_model
      assert_same task, action.returned_type
      speed = action.find_arg(:speed)
      assert_equal [true, nil, 'in m/s'], [speed.required, speed.default, speed.doc]
      mode = action.find_arg(:mode)
      assert_equal [false, 'slow'], [mode.required, mode.default]
      refute action.has_arg?(:other)
    end

    # A task made from requirements knows them (Syskit's +requirements+),
    # and is abstract when they are marked so.
    def test_a_plain_component_instanciated_knows_its_requirements
      component = Component.new_submodel
      plan = Test::Plan.new
      task = component.to_instance_requirements.instanciate(plan)
      assert_kind_of component, task
      refute task.abstract?
      assert_equal InstanceRequirements.new([component]), task.requirements.with_models([component])
      abstract = component.to_instance_requirements.abstract.instanciate(plan)
      assert abstract.abstract?
      assert abstract.requirements.abstract?
      assert plan.include?(abstract)
    end

    # A task to be planned from requirements (Syskit's +as_plan+): the
    # requirements, with the arguments given, are its planning task's.
    def test_a_task_to_be_planned_carries_its_requirements
      _, task = pose_and_task
      requirements = InstanceRequirements.new([task.fix_srv])
      planned = requirements.as_plan(job_id: 3, speed: 2)
      assert_kind_of task, planned
      assert_equal({ speed: 2 }, planned.arguments.each_assigned_argument.to_h)
      refute planned.arguments.set?(:job_id)
      assert planned.planning_task.arguments.set?(:job_id)
      assert_empty requirements.arguments
      assert_equal [requirements.with_arguments(speed: 2), 3],
                   [planned.planning_task.requirements, planned.planning_task.job_id]
    end

    # Selecting a service given as requirements brings their arguments.
    def test_a_service_selected_with_its_arguments
      _, task = pose_and_task
      with_key = InstanceRequirements.new([task]).select_service(task.with_arguments(key: 1).fix_srv)
      assert_equal [task.fix_srv, { key: 1 }], [with_key.model, with_key.arguments]
    end

    # As Syskit's: statements change requirements made on the spot; those
    # a model, a profile or an injection holds give a changed copy.
    def test_statements_change_requirements_that_nothing_holds
      _, task = pose_and_task
      requirements = InstanceRequirements.new([task])
      assert_same requirements, requirements.with_arguments(a: 1).select_service(task.fix_srv)
      assert_equal [{ a: 1 }, task.fix_srv], [requirements.arguments, requirements.service]
      assert_equal task.fix_srv, requirements.model
      assert_nil requirements.unselect_service.service
      assert_same task, requirements.model
      copy = requirements.dup
      copy.with_arguments(b: 2)
      assert_equal({ a: 1 }, requirements.arguments)
      DependencyInjection.new('x' => requirements)
      refute_same requirements, requirements.with_arguments(c: 3)
      assert_equal({ a: 1 }, requirements.arguments)
    end

    # As Syskit's +use+: a model selected by name for a child must derive
    # from the child's component model; children are read off a
    # composition's requirements only.
    def test_children_of_requirements_and_what_use_selects_for_them
      pose, task = pose_and_task
      other = TaskContext.new_submodel(name: 'Other')
      cmp = Composition.new_submodel(name: 'Cmp') { add task, as: 'nav' }
      error = assert_raises(InvalidSelection) { cmp.use('nav' => other) }
      assert_match(/'nav'|nav_child/, error.message)
      assert cmp.use('nav' => task.new_submodel)
      assert_equal ['nav'], cmp.to_instance_requirements.each_child.map(&:first)
      assert_raises(ArgumentError) { task.to_instance_requirements.find_child('nav') }
      assert_nil InstanceRequirements.new([task.fix_srv]).to_component_model.service
      requirements = task.to_instance_requirements
      assert_equal requirements.out_port, requirements.out_port.to_component_port
      refute_nil pose
    end

    # A composition child's port is the port of that child, however it was
    # made (Syskit's tests make one with Models::OutputPort.new(child, ...)).
    def test_a_child_port_is_a_port_of_the_child
      pose, task = pose_and_task
      cmp = Composition.new_submodel(name: 'Cmp') { add pose, as: 'nav' }
      port = cmp.nav_child.pose_port
      assert_equal Models::OutputPort.new(cmp.nav_child, pose.pose_port.orogen_model), port
      assert_equal port, Models::OutputPort.new(cmp.nav_child, pose.pose_port.orogen_model)
      refute_equal Models::OutputPort.new(task, pose.pose_port.orogen_model), port
    end

    def pose_and_task
      tracker_app
      pose = DataService.new_submodel(name: 'Pose') { output_port 'pose', '/double' }
      task = TaskContext.new_submodel(name: 'Task') { output_port 'out', '/double' }
      task.provides pose, as: 'fix'
      [pose, task]
    end
  end
end
