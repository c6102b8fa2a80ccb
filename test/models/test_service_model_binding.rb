# frozen_string_literal: true

require 'helper'
require 'syskit/test/plan'

module Syskit
  # What a data service model says of the components providing it, as
  # Syskit's service models answer: the models it provides, the service of
  # a component bound to it, its placeholder, and for a device the loaded
  # drivers.
  class TestServiceModelBinding < Minitest::Test
    FILES = {
      'models/devices/things.rb' => <<~RUBY,
        module MyApp
          data_service_type('Pose') { output_port 'pose', '/double' }
          data_service_type('Cmd') { input_port 'cmd', '/double' }
          module Devices
            device_type('Gps') { provides Pose }
            device_type('Camera') { output_port 'image', '/int32_t' }
            device_type('Lidar')
          end
        end
      RUBY
      'models/orogen/nav.orogen' => <<~RUBY,
        name 'nav'
        task_context 'GpsTask' do
          output_port 'fix', '/double'
          input_port 'cmd', '/double'
        end
        task_context 'StereoTask' do
          output_port 'left', '/int32_t'
          output_port 'right', '/int32_t'
        end
        task_context 'MonoTask' do
          output_port 'image', '/int32_t'
        end
      RUBY
      'models/orogen/nav.rb' => <<~RUBY
        Syskit.extend_model OroGen.nav.GpsTask do
          driver_for MyApp::Devices::Gps, as: 'gps'
          provides MyApp::Cmd, as: 'cmd'
        end
        Syskit.extend_model OroGen.nav.StereoTask do
          driver_for MyApp::Devices::Camera, as: 'left', 'image' => 'left'
          driver_for MyApp::Devices::Camera, as: 'right', 'image' => 'right'
        end
        Syskit.extend_model(OroGen.nav.MonoTask) { driver_for MyApp::Devices::Camera, as: 'camera' }
      RUBY
    }.freeze

    def setup
      super
      @root = my_app(nil, FILES)
      load_app(@root, everything: true)
    end

    def test_parent_models_are_what_a_model_provides
      assert_equal [MyApp::Pose, Syskit::Device, Syskit::DataService], MyApp::Devices::Gps.parent_models
      assert_equal [Syskit::DataService], MyApp::Pose.parent_models
    end

    def test_binding_a_component_to_a_service_model
      task = OroGen.nav.GpsTask
      srv = MyApp::Pose.bind(task)
      assert_equal 'gps', srv.full_name
      assert_equal 'fix', srv.pose_port.to_component_port.name
      assert_equal task.cmd_srv, MyApp::Cmd.try_bind(task)
      assert_equal srv, MyApp::Pose.try_bind(task.gps_srv), 'a service is seen as the model'
      assert_nil MyApp::Cmd.try_bind(task.gps_srv)
    end

    def test_binding_fails_when_a_component_has_none_or_several
      assert_nil MyApp::Devices::Camera.try_bind(OroGen.nav.StereoTask), 'ambiguous'
      error = assert_raises(AmbiguousServiceSelection) { MyApp::Devices::Camera.bind(OroGen.nav.StereoTask) }
      assert_match 'nav::StereoTask has several services of type MyApp::Devices::Camera: left, right', error.message
      error = assert_raises(DeclarationError) { MyApp::Pose.bind(OroGen.nav.StereoTask) }
      assert_match 'nav::StereoTask provides no service of type MyApp::Pose', error.message
    end

    def test_the_placeholder_model_of_a_service
      placeholder = MyApp::Pose.placeholder_model
      assert_same placeholder, MyApp::Pose.placeholder_model
      assert placeholder.placeholder?
      assert placeholder.abstract?
      assert placeholder.fullfills?(MyApp::Pose)
      assert_equal [MyApp::Pose], placeholder.proxied_data_service_models
      refute OroGen.nav.GpsTask.placeholder?
    end

    def test_placeholder_tasks_of_a_service
      task = MyApp::Pose.create_placeholder_task
      assert_kind_of MyApp::Pose.placeholder_model, task
      assert task.abstract?
      refute OroGen.nav.GpsTask.new.abstract?

      plan = Test::Plan.new
      added = MyApp::Pose.instanciate(plan)
      assert_kind_of MyApp::Pose.placeholder_model, added
      assert plan.include?(added)
    end

    def test_a_placeholder_of_several_services
      both = Models::Placeholder.for([MyApp::Pose, MyApp::Cmd])
      assert both.fullfills?([MyApp::Pose, MyApp::Cmd])
      assert_equal %w[cmd pose], both.ports.keys.sort
      assert_equal MyApp::Pose, both.find_data_service_from_type(MyApp::Pose).model
    end

    def test_a_placeholder_derived_from_a_component_model
      mono = OroGen.nav.MonoTask
      assert_same mono, Models::Placeholder.for([mono, MyApp::Devices::Camera]), 'it provides them all'
      on_mono = Models::Placeholder.for([mono, MyApp::Cmd])
      assert on_mono < mono
      assert_equal [MyApp::Cmd], on_mono.proxied_data_service_models
      assert_same OroGen.nav.GpsTask.gps_srv, Models::Placeholder.for([OroGen.nav.GpsTask.gps_srv, MyApp::Pose])
      error = assert_raises(DeclarationError) { Models::Placeholder.for([mono, OroGen.nav.GpsTask]) }
      assert_match 'a placeholder derives from one component model at most', error.message
    end

    def test_the_drivers_of_a_device_model
      assert_equal [OroGen.nav.GpsTask], MyApp::Devices::Gps.find_all_drivers
      assert_equal OroGen.nav.GpsTask, MyApp::Devices::Gps.default_driver
      assert_equal [OroGen.nav.MonoTask, OroGen.nav.StereoTask], MyApp::Devices::Camera.find_all_drivers
      error = assert_raises(Ambiguous) { MyApp::Devices::Camera.default_driver }
      assert_match 'several task models drive (nav::MonoTask, nav::StereoTask) MyApp::Devices::Camera', error.message
      error = assert_raises(ArgumentError) { MyApp::Devices::Lidar.default_driver }
      assert_match 'no loaded task model drives MyApp::Devices::Lidar', error.message
    end

    def test_drivers_made_in_ruby_are_found_too
      ruby_driver = TaskContext.new_submodel { output_port 'range', '/double' }
      ruby_driver.driver_for MyApp::Devices::Lidar, as: 'lidar'
      assert_equal [ruby_driver], MyApp::Devices::Lidar.find_all_drivers
      refute_includes MyApp::Devices::Lidar.find_all_drivers, MyApp::Devices::Lidar.placeholder_model
    end
  end
end
