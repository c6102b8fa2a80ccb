# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # A task model seen through the models it fullfills (requirements'
  # +as+, Syskit's FacetedAccess): the required models' ports, each
  # standing for the task's port it maps to.
  class TestFacetedAccess < Minitest::Test
    include CompositionTestHelper

    def setup
      super
      load_rig
      @pose = DataService.new_submodel(name: 'Pose') { output_port 'pose', '/double' }
      @heading = DataService.new_submodel(name: 'Heading') { output_port 'pose', '/float' }
      @base = TaskContext.new_submodel(name: 'Base') { output_port 'status', '/int32_t' }
      @task = @base.new_submodel(name: 'Tracker') do
        output_port 'front', '/double'
        output_port 'yaw', '/float'
      end
      @task.provides @pose, as: 'front_pose', 'pose' => 'front'
      @task.provides @heading, as: 'yaw', 'pose' => 'yaw'
    end

    def test_task_models_have_port_readers
      assert_same @task.find_output_port('front'), @task.front_port
      assert_equal @base.find_output_port('status').name, @task.status_port.name
      assert_same @task.find_port('front'), @task.front_port
      assert_same @task, @task.status_port.component_model
    end

    def test_ports_stand_for_the_tasks_ports
      facet = @task.to_instance_requirements.as(@pose)
      assert_kind_of Models::FacetedAccess, facet
      port = facet.find_port('pose')
      assert_same facet, port.component_model
      assert_same @task.front_port, port.to_component_port
      assert_nil facet.find_port('front')
    end

    def test_the_component_model_of_a_placeholder_is_required_too
      facet = Models::FacetedAccess.new(@task, Models::Placeholder.for([@base, @pose]))
      required = facet.find_ports_on_required('pose') + facet.find_ports_on_required('status')
      assert_equal [@pose.pose_port, @base.status_port], required
      assert_equal [@task.status_port].to_set, facet.find_all_port_mappings_for('status')
      assert_equal %w[pose state status], facet.ports.keys.sort
    end

    def test_a_name_mapped_to_several_ports_is_ambiguous
      facet = Models::FacetedAccess.new(@task, Models::Placeholder.for([@pose, @heading]))
      assert_equal [@task.front_port, @task.yaw_port].to_set, facet.find_all_port_mappings_for('pose')
      assert_raises(AmbiguousPortOnCompositeModel) { facet.find_port('pose') }
    end

    def test_a_placeholder_of_services_sharing_a_port_name_keeps_both_ports
      placeholder = Models::Placeholder.for([@pose, @heading])
      assert_equal '/double', placeholder.find_data_service_from_type(@pose).task_port_for(@pose, 'pose').type.name
      assert_equal '/float', placeholder.find_data_service_from_type(@heading).task_port_for(@heading, 'pose').type.name
    end

    def test_selected_is_the_requirements_with_the_service_providing_the_required_one
      facet = @task.to_instance_requirements.as(@pose)
      assert_equal @task.to_instance_requirements.select_service(@task.front_pose_srv), facet.selected
      placeholder = Models::FacetedAccess.new(@task, Models::Placeholder.for([@base, @pose]))
      assert_nil placeholder.selected.service
    end

    def test_seeing_a_selected_service_through_a_parent_model_keeps_that_service
      odometry = DataService.new_submodel(name: 'Odometry') { output_port 'odom', '/double' }
      odometry.provides @pose, 'pose' => 'odom'
      task = TaskContext.new_submodel(name: 'Wheels') { output_port 'ticks', '/double' }
      task.provides odometry, as: 'odom'
      requirements = task.to_instance_requirements.select_service(task.odom_srv)
      assert_same task.odom_srv, requirements.as(@pose).service
      assert_raises(DeclarationError) { requirements.as(@heading) }
      placeholder_srv = odometry.placeholder_model.find_data_service_from_type(odometry)
      on_placeholder = InstanceRequirements.new([odometry]).select_service(placeholder_srv)
      assert_same placeholder_srv, on_placeholder.as(@pose).service
    end
  end
end
