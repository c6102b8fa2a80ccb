# frozen_string_literal: true

require 'helper'

module Syskit
  # The services of tasks (Syskit::BoundDataService) and how a task model's
  # service binds to a task, as Syskit's tests use them: one object per
  # service of a task, lookups by the service's port names, and binding
  # through placeholders and dynamic service instances.
  class TestServiceBinding < Minitest::Test
    FILES = SelfTest::SERVICE_FILES

    def setup
      super
      load_app(my_app(nil, FILES), everything: true)
      @task_m = TaskContext.new_submodel(name: 'T') do
        output_port 'out', '/double'
        input_port 'in', '/double'
        output_port 'other', '/int32_t'
        provides MyApp::Odometry, as: 'odo', 'pose' => 'out'
        provides MyApp::Cmd, as: 'cmd', slave_of: 'odo'
      end
    end

    def test_the_services_of_a_task
      task = @task_m.new
      assert_same task.odo_srv, task.find_data_service('odo')
      assert_same task.find_data_service('odo.cmd'), task.odo_srv.cmd_srv
      assert_same task.odo_srv.cmd_srv, task.odo_srv.find_data_service('cmd')
      assert_equal [task.odo_srv.as(MyApp::Pose)], task.find_all_data_services_from_type(MyApp::Pose)
      assert_equal task.odo_srv.as(MyApp::Pose), MyApp::Pose.try_bind(task)
      assert_equal [MyApp::Odometry, MyApp::Pose, DataService], task.odo_srv.each_fullfilled_model.to_a
      assert task.fullfills?(MyApp::Cmd)
    end

    def test_tasks_are_of_the_service_models_their_model_provides
      task = @task_m.new
      assert_kind_of MyApp::Odometry, task
      assert_kind_of MyApp::Pose, task
      assert_kind_of MyApp::Cmd, task
      assert_operator @task_m, :<, MyApp::Pose
      refute_kind_of MyApp::Odometry, TaskContext.new_submodel.new
    end

    def test_a_task_service_finds_ports_by_the_service_port_names
      srv = @task_m.new.odo_srv
      port = srv.find_output_port('pose')
      assert_equal 'pose', port.name
      assert_equal srv, port.component
      assert_equal 'out', port.to_component_port.name
      assert_nil srv.find_input_port('pose'), 'an output'
      assert_nil srv.find_output_port('out'), 'the task port name'
      assert_nil srv.find_output_port('other')
    end

    def test_a_service_model_binds_to_tasks_of_its_model
      srv_m = @task_m.odo_srv
      task = @task_m.new
      assert_equal task.odo_srv, srv_m.bind(task)
      assert_same task.odo_srv, srv_m.bind(task.odo_srv)
      assert_equal @task_m.new_submodel.new.odo_srv.full_name, srv_m.bind(@task_m.new_submodel.new).full_name
      other = TaskContext.new_submodel.new
      error = assert_raises(ArgumentError) { srv_m.bind(other) }
      assert_equal "cannot bind #{srv_m} on #{other}: does not fullfill #{@task_m}", error.message
    end

    def test_a_placeholder_service_binds_by_name_or_by_type
      heading = DataService.new_submodel { output_port 'heading', '/double' }
      placeholder = Models::Placeholder.for([heading], component_model: @task_m)
      sub_m = @task_m.new_submodel
      sub_m.provides heading, as: 'h', 'heading' => 'out'
      task = sub_m.new
      assert_equal @task_m.odo_srv.bind(task), placeholder.odo_srv.bind(task), 'a service of the base model'
      assert_equal task.h_srv, placeholder.m0_srv.bind(task), 'a service it stands for'
      sub_m.provides heading, as: 'h2', 'heading' => 'out'
      error = assert_raises(AmbiguousServiceSelection) { placeholder.m0_srv.bind(sub_m.new) }
      assert_match 'h, h2', error.message
    end

    def test_a_service_model_fullfills_placeholders_of_what_it_provides
      srv_m = @task_m.odo_srv
      assert srv_m.fullfills?(MyApp::Pose.placeholder_model)
      refute srv_m.fullfills?(MyApp::Cmd.placeholder_model)
      refute srv_m.fullfills?(@task_m)
      assert_equal [MyApp::Odometry], srv_m.fullfilled_model
      assert_equal [MyApp::Odometry, MyApp::Pose, DataService], srv_m.each_fullfilled_model.to_a
      assert_same srv_m, srv_m.attach(srv_m)
      assert @task_m.new_submodel.fullfills?(MyApp::Pose.placeholder_model)
    end

    def test_ports_of_task_and_service_models_are_never_connected
      refute MyApp::Pose.pose_port.connected_to?(MyApp::Cmd.cmd_port)
      refute @task_m.odo_srv.pose_port.connected_to?(@task_m.in_port)
      refute @task_m.out_port.connected_to?(@task_m.in_port)
    end

    def test_instances_of_a_dynamic_service_bind_across_specializations
      cmd = MyApp::Cmd
      task_m = TaskContext.new_submodel do
        input_port 'in', '/double'
        dynamic_service(cmd, as: 'dyn') { provides cmd, 'cmd' => 'in' }
        dynamic_service(cmd, as: 'other') { provides cmd, 'cmd' => 'in' }
      end
      left = task_m.specialize.tap { |m| m.require_dynamic_service('dyn', as: 'x') }
      right = task_m.specialize.tap { |m| m.require_dynamic_service('dyn', as: 'x') }
      task = right.new
      assert_same task.x_srv, left.x_srv.bind(task)
      wrong = task_m.specialize.tap { |m| m.require_dynamic_service('other', as: 'x') }.new
      assert_raises(ArgumentError) { left.x_srv.bind(wrong) }
    end
  end
end
