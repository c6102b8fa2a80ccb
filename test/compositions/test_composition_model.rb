# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Composition models as Syskit defines them: children, ports, exports,
  # connections, services and named configurations.
  class TestCompositionModel < Minitest::Test
    include CompositionTestHelper::OnRig

    def test_a_composition_model_takes_the_name_of_its_constant
      model = new_cmp
      Rig.const_set(:Cmp, model)
      assert_equal 'Rig::Cmp', model.name
    ensure
      Rig.send(:remove_const, :Cmp) if Rig.const_defined?(:Cmp, false)
    end

    def test_add_returns_the_child_reachable_by_name
      model = new_cmp
      child = model.add(Rig::Services::Pose, as: 'pose')
      assert_kind_of Models::CompositionChild, child
      assert_same child, model.pose_child
      assert_same child, model.find_child('pose')
      assert_equal 'pose', child.child_name
      assert_same model, child.composition_model
      assert_same Rig::Services::Pose.placeholder_model, child.model
      assert_nil model.find_child('nothing')
    end

    def test_a_childs_model_is_the_placeholder_of_what_it_requires
      model = new_cmp do
        add OroGen.rig.Follower, as: 'follow'
        add [Rig::Services::Pose, Rig::Services::SpeedSource], as: 'both'
      end
      assert_same OroGen.rig.Follower, model.follow_child.model
      both = model.both_child.model
      assert both.placeholder?
      assert_equal [Rig::Services::Pose, Rig::Services::SpeedSource], both.proxied_data_service_models
      model.overload 'follow', Rig::Services::Pose
      assert_equal [Rig::Services::Pose], model.follow_child.model.proxied_data_service_models
      assert_same OroGen.rig.Follower, model.follow_child.model.proxied_component_model
    end

    def test_a_child_needs_a_name
      error = assert_raises(DeclarationError) { new_cmp { add Rig::Services::Pose } }
      assert_match(/add needs a child name \(as:\)/, error.message)
      assert_equal File.expand_path(__FILE__), error.location.path
    end

    def test_a_child_must_be_a_model
      error = assert_raises(DeclarationError) { new_cmp { add 'Pose', as: 'pose' } }
      assert_match(/add expects a task, composition, service or device model, got "Pose"/, error.message)
    end

    def test_a_submodel_sees_its_parents_children_as_its_own
      parent = new_cmp { add Rig::Services::Pose, as: 'pose' }
      child_model = parent.new_submodel
      assert_same child_model, child_model.find_child('pose').composition_model
      assert_same parent, parent.find_child('pose').composition_model
      assert_same child_model.pose_child, child_model.pose_child
    end

    def test_overload_refines_a_child_with_a_model_that_fullfills_it
      parent = new_cmp { add Rig::Services::Pose, as: 'pose' }
      model = parent.new_submodel
      model.overload 'pose', Rig::Services::Odometry
      assert_equal [Rig::Services::Odometry], model.pose_child.models
      assert_equal [Rig::Services::Pose], parent.pose_child.models
    end

    def test_overload_with_an_unrelated_service_requires_both
      model = new_cmp { add Rig::Services::Pose, as: 'x' }
      model.overload 'x', Rig::Services::SpeedSource
      assert_equal [Rig::Services::Pose, Rig::Services::SpeedSource], model.x_child.models
      assert model.x_child.fullfills?(Rig::Services::Pose)
      assert model.x_child.fullfills?(Rig::Services::SpeedSource)
    end

    def test_overload_refuses_two_unrelated_task_models
      model = new_cmp { add OroGen.rig.Follower, as: 'x' }
      error = assert_raises(DeclarationError) { model.overload 'x', OroGen.rig.Splitter }
      assert_match(/cannot be both a rig::Follower and a rig::Splitter/, error.message)
    end

    def test_overload_of_an_unknown_child
      model = new_cmp { add Rig::Services::Pose, as: 'pose' }
      error = assert_raises(DeclarationError) { model.overload 'poses', Rig::Services::Odometry }
      assert_match(/poses is not a child of .*did you mean 'pose'/, error.message)
    end

    def test_overload_keeps_the_arguments_of_the_child
      model = new_cmp { add Rig::Services::Pose, as: 'pose' }
      model.overload 'pose', model.pose_child.requirements.with_arguments(rate: 10)
      assert_equal({ rate: 10 }, model.pose_child.arguments)
    end

    def test_child_requirement_statements_change_the_child_in_place
      model = new_cmp
      child = model.add(OroGen.rig.Follower, as: 'follow').with_arguments(gain: 2).with_conf('default', 'fast')
      assert_same child, model.follow_child
      assert_equal({ gain: 2 }, child.arguments)
      assert_equal %w[default fast], child.requirements.conf
    end

    def test_add_main_and_add_optional
      model = new_cmp do
        add_main OroGen.rig.Follower, as: 'follow'
        add_optional Rig::Services::Pose, as: 'pose'
      end
      assert_same model.follow_child, model.main_task
      assert model.pose_child.optional?
      refute model.follow_child.optional?
      error = assert_raises(DeclarationError) { model.add_main(OroGen.rig.Splitter, as: 'split') }
      assert_match(/already has a main child \(follow\)/, error.message)
    end

    def test_children_ports_are_those_of_their_models
      model = new_cmp do
        add OroGen.rig.Follower, as: 'follow'
        add Rig::Services::Odometry, as: 'odom'
      end
      assert_equal %w[command pose state], model.follow_child.ports.keys.sort
      assert_equal %w[odometry], model.odom_child.ports.keys
      port = model.follow_child.command_port
      assert_equal :output, port.direction
      assert_equal '/double', port.type.name
      assert_same model.follow_child, port.component_model
    end

    def test_connect_to_records_the_connection
      model = new_cmp do
        add Rig::Services::Odometry, as: 'odom'
        add OroGen.rig.Follower, as: 'follow'
        odom_child.odometry_port.connect_to follow_child.pose_port
      end
      assert model.odom_child.odometry_port.connected_to?(model.follow_child.pose_port)
      refute model.follow_child.command_port.connected_to?(model.follow_child.pose_port)
    end

    def test_connect_to_refuses_ports_of_different_types
      model = new_cmp do
        add OroGen.rig.Splitter, as: 'split'
        add OroGen.rig.Follower, as: 'follow'
      end
      error = assert_raises(DeclarationError) { model.split_child.left_port.connect_to model.follow_child.pose_port }
      assert_match(%r{cannot connect .*split_child.left_port \(/double\) to .*follow_child.pose_port .*types differ},
                   error.message)
      assert_equal File.expand_path(__FILE__), error.location.path
    end

    def test_connect_to_refuses_an_input_as_source
      model = new_cmp do
        add OroGen.rig.Splitter, as: 'split'
        add OroGen.rig.Follower, as: 'follow'
      end
      error = assert_raises(DeclarationError) { model.split_child.in_port.connect_to model.follow_child.command_port }
      assert_match(/cannot connect .*in_port \(input\) to .*command_port \(output\)/, error.message)
    end

    def test_connect_to_checks_policies
      model = new_cmp do
        add OroGen.rig.Follower, as: 'follow'
        add OroGen.rig.Splitter, as: 'split'
      end
      error = assert_raises(DeclarationError) do
        model.follow_child.command_port.connect_to model.split_child.in_port, type: :queue
      end
      assert_match(/unknown connection type :queue/, error.message)
      error = assert_raises(DeclarationError) do
        model.follow_child.command_port.connect_to model.split_child.in_port, sise: 10
      end
      assert_match(/unknown connection policy option sise:/, error.message)
    end

    def test_a_child_connects_to_another_by_type
      model = new_cmp do
        add OroGen.rig.Tracker, as: 'track'
        add OroGen.rig.Follower, as: 'follow'
      end
      error = assert_raises(DeclarationError) { model.follow_child.connect_to model.track_child }
      assert_match(/has no output port of the type of an input of/, error.message)
      model.add(Rig::Services::Pose, as: 'pose')
      model.pose_child.connect_to model.follow_child
      assert model.pose_child.pose_port.connected_to?(model.follow_child.pose_port)
    end

    def test_connected_to_follows_the_services_a_child_is_overloaded_with
      model = new_cmp do
        add Rig::Services::Pose, as: 'pose'
        add OroGen.rig.Follower, as: 'follow'
      end
      model.overload 'pose', Rig::Services::Odometry
      model.pose_child.odometry_port.connect_to model.follow_child.pose_port
      assert model.pose_child.as(Rig::Services::Pose).pose_port.connected_to?(model.follow_child.pose_port)
    end

    def test_export_makes_a_child_port_a_port_of_the_composition
      model = new_cmp do
        add OroGen.rig.Follower, as: 'follow'
        export follow_child.pose_port, as: 'target'
        export follow_child.command_port
      end
      assert_equal %w[command target], model.ports.keys.sort
      assert_equal :input, model.target_port.direction
      assert model.has_port?('command')
      assert model.exported_port?(model.follow_child.pose_port)
      assert_equal model.follow_child.pose_port, model.find_exported_input('target')
      assert_nil model.find_exported_output('target')
    end

    def test_export_twice_under_one_name
      model = new_cmp do
        add OroGen.rig.Splitter, as: 'split'
        export split_child.left_port, as: 'out'
      end
      model.export model.split_child.left_port, as: 'out'
      error = assert_raises(DeclarationError) { model.export model.split_child.right_port, as: 'out' }
      assert_match(/already exports .*left_port as 'out'/, error.message)
      assert_match(/as: 'other_name'/, error.hint)
    end

    def test_export_refuses_a_port_of_another_model
      other = new_cmp { add OroGen.rig.Splitter, as: 'split' }
      model = new_cmp
      error = assert_raises(DeclarationError) { model.export other.split_child.left_port }
      assert_match(/export expects a port of a child of/, error.message)
    end

    def test_provides_maps_a_service_on_exported_ports
      model = new_cmp do
        add Rig::Services::Odometry, as: 'odom'
        export odom_child.odometry_port, as: 'odom_out'
        provides Rig::Services::Pose, as: 'pose'
      end
      assert model.fullfills?(Rig::Services::Pose)
      assert model.provides?(Rig::Services::Pose)
      assert_equal({ 'pose' => 'odom_out' }, model.pose_srv.port_mappings)
      error = assert_raises(DeclarationError) { model.provides Rig::Services::SpeedCommand, as: 'cmd' }
      assert_match(/has no input port of type .*double/, error.message)
    end

    def test_conf_gives_sections_to_children
      model = new_cmp { add OroGen.rig.Follower, as: 'follow' }
      model.conf 'fast', model.follow_child => %w[default fast]
      assert_equal({ 'fast' => { 'follow' => %w[default fast] } }, model.configurations)
      error = assert_raises(DeclarationError) { model.conf 'slow', 'folow' => ['slow'] }
      assert_match(/conf 'slow' names folow, which is not a child/, error.message)
    end

    def test_arguments_have_defaults_and_readers
      model = new_cmp { argument :speed, default: 0.5 }
      assert_equal({ speed: 0.5 }, model.argument_defaults)
      assert_equal 0.5, model.new.speed
      assert_equal 2, model.new(speed: 2).speed
    end

    # As on a Roby task, arguments given to new go through the writer a
    # model defines to check or derive them.
    def test_arguments_go_through_the_model_s_writers
      model = new_cmp do
        argument :speed
        define_method(:speed=) do |value|
          raise ArgumentError, "speed #{value} is negative" if value.negative?

          arguments[:speed] = value.round(1)
        end
      end
      assert_equal 1.3, model.new(speed: 1.26).speed
      assert_raises(ArgumentError) { model.new(speed: -1) }
      delayed = model.from(:parent_task).speed
      assert_same delayed, model.new(speed: delayed).arguments[:speed], 'delayed: kept as it is'
      task = model.new(name: 'not the task name')
      assert_equal ['not the task name', nil], [task.arguments[:name], task.name], 'not an argument: kept as it is'
    end

    def test_runtime_statements_are_accepted_with_a_warning
      app = Syskit.app
      model = new_cmp do
        add OroGen.rig.Follower, as: 'follow'
        event :arrived
        script { poll { nil } }
      end
      assert_equal %w[follow], model.child_names
      warnings = app.problems.map(&:message).grep(/not modelled/)
      assert_equal 2, warnings.size, warnings.join("\n")
      assert_match(/event in /, warnings[0])
    end

    def test_runtime_options_of_add_are_a_warning
      app = Syskit.app
      new_cmp { add OroGen.rig.Follower, as: 'follow', success: :stop }
      assert_match(/add's success option: not modelled/, app.problems.last.message)
      error = assert_raises(DeclarationError) { new_cmp { add OroGen.rig.Follower, as: 'f', color: :red } }
      assert_match(/unknown option color: for add/, error.message)
    end

    def test_use_gives_requirements
      model = new_cmp { add Rig::Services::Pose, as: 'pose' }
      requirements = model.use('pose' => OroGen.rig.Tracker.front_pose_srv)
      assert_kind_of InstanceRequirements, requirements
      assert_equal [model], requirements.models
      assert requirements.composition?
      assert_match(/use\('pose' => /, requirements.to_s)
    end

    def test_use_refuses_what_is_not_a_model
      model = new_cmp { add Rig::Services::Pose, as: 'pose' }
      error = assert_raises(DeclarationError) { model.use('pose' => 42) }
      assert_match(/use cannot select 42 for 'pose': it is not a model, device or definition/, error.message)
      assert_equal File.expand_path(__FILE__), error.location.path
    end

    def test_is_model_and_fullfilled_models
      model = new_cmp
      assert Models.is_model?(model)
      assert model.fullfills?(Composition)
      assert model.fullfills?(Component)
      refute model.fullfills?(TaskContext)
      assert_includes model.each_fullfilled_model.to_a, Composition
    end
  end
end
