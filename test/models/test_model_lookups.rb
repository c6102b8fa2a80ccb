# frozen_string_literal: true

require 'helper'

module Syskit
  # Model introspection that driver authors and tests call, as Syskit's
  # model tests describe it: each_fullfilled_model, new_submodel,
  # short_name, fullfills?, the driver services of a task model, and the
  # options of com_bus_type.
  class TestModelLookups < Minitest::Test
    MODELS = <<~RUBY
      module MyApp
        data_service_type 'Pose'
        data_service_type 'Rate'
        module Devices
          device_type 'Camera'
          device_type 'Stereo' do
            provides Pose
            provides Camera
          end
          com_bus_type 'Serial', message_type: '/double'
          com_bus_type 'Rs485' do
            provides Serial
          end
          com_bus_type 'Lazy', message_type: '/double', lazy_dispatch: true, override_policy: false
        end
      end
    RUBY

    def setup
      super
      @root = my_app(nil, 'models/devices/things.rb' => MODELS)
      load_app(@root, everything: true)
    end

    def test_each_fullfilled_model_lists_the_model_what_it_provides_last_first_then_the_roots
      assert_equal [MyApp::Pose, Syskit::DataService], MyApp::Pose.each_fullfilled_model.to_a
      assert_equal [MyApp::Devices::Camera, Syskit::Device, Syskit::DataService],
                   MyApp::Devices::Camera.each_fullfilled_model.to_a
      assert_equal [MyApp::Devices::Stereo, MyApp::Devices::Camera, MyApp::Pose, Syskit::Device, Syskit::DataService],
                   MyApp::Devices::Stereo.each_fullfilled_model.to_a
      assert_equal [MyApp::Devices::Rs485, MyApp::Devices::Serial, Syskit::ComBus, Syskit::Device, Syskit::DataService],
                   MyApp::Devices::Rs485.each_fullfilled_model.to_a
    end

    def test_fullfills_takes_a_model_or_a_list
      stereo = MyApp::Devices::Stereo
      assert stereo.fullfills?(MyApp::Pose)
      assert stereo.fullfills?([MyApp::Pose, MyApp::Devices::Camera])
      refute stereo.fullfills?([MyApp::Pose, MyApp::Rate])
      refute MyApp::Devices::Camera.fullfills?(stereo)
    end

    def test_short_name_is_the_name_or_what_stands_for_it
      assert_equal 'MyApp::Devices::Camera', MyApp::Devices::Camera.short_name
      assert_equal 'Srv', Syskit::DataService.new_submodel(name: 'Srv').short_name
      anonymous = Syskit::Device.new_submodel
      assert_match(/\Aanonymous device #\d+\z/, anonymous.short_name)
      assert_equal anonymous.short_name, anonymous.to_s
    end

    # As Syskit's, two anonymous models are shown apart: Syskit's tests
    # name services after them (+provides srv, as: srv.to_s+).
    def test_anonymous_models_are_shown_apart
      first = Syskit::DataService.new_submodel
      second = Syskit::DataService.new_submodel
      refute_equal first.to_s, second.to_s
      task_m = Syskit::TaskContext.new_submodel
      task_m.provides first, as: first.to_s
      task_m.provides second, as: second.to_s
      assert_equal [first, second], task_m.each_data_service.map(&:model)
    end

    # As Syskit's: short_name is to_s, whatever shows the model otherwise
    # (a custom model class, a model given a to_s of its own).
    def test_short_name_follows_to_s
      srv = Syskit::DataService.new_submodel
      srv.define_singleton_method(:to_s) { 'my_name' }
      assert_equal 'my_name', srv.short_name
      labelled = Class.new(Models::DeviceModel) { def to_s = "labelled #{name}" }
      assert_equal 'labelled Probe', labelled.new(name: 'Probe').short_name
      task = OroGen.imu.Task
      assert_equal 'imu::Task', task.short_name
      task.define_singleton_method(:to_s) { 'the IMU driver' }
      assert_equal 'the IMU driver', task.short_name
    end

    def test_new_submodel_provides_its_model_and_evaluates_the_block
      camera = MyApp::Devices::Camera.new_submodel(name: 'Thermal') { output_port 'image', '/double' }
      assert_instance_of Models::DeviceModel, camera
      assert_equal 'Thermal', camera.name
      assert_equal [camera, MyApp::Devices::Camera, Syskit::Device, Syskit::DataService],
                   camera.each_fullfilled_model.to_a
      assert_equal ['image'], camera.ports.keys
      refute Syskit::Device.new_submodel.name
    end

    # Every component model makes submodels the same way: Component itself
    # (a plain component providing services), compositions, task contexts.
    def test_component_models_make_named_submodels_with_their_block
      component = Syskit::Component.new_submodel(name: 'Plain') { provides MyApp::Pose, as: 'pose' }
      assert_operator component, :<, Syskit::Component
      assert_equal 'Plain', component.name
      assert_equal MyApp::Pose, component.pose_srv.model
      assert_equal 'Plain', component.new_submodel(name: 'Plain').name
      refute Syskit::Component.new_submodel.name
      cmp = Syskit::Composition.new_submodel(name: 'Cmp') { add MyApp::Pose, as: 'pose' }
      assert_equal ['pose'], cmp.child_names
      assert_equal 'Cmp', cmp.name
      task = Syskit::TaskContext.new_submodel(name: 'Task') { output_port 'out', '/double' }
      assert_operator task, :<, Syskit::RubyTaskContext
      assert_equal %w[Task out], [task.name, task.new_submodel.find_output_port('out').name]
    end

    def test_a_bus_submodel_needs_a_message_type_of_its_own_or_of_its_parent
      assert_equal '/double', MyApp::Devices::Serial.new_submodel.message_type.name
      assert_equal '/int32_t', Syskit::ComBus.new_submodel(message_type: '/int32_t').message_type.name
      assert_raises(DeclarationError) { Syskit::ComBus.new_submodel }
      assert_raises(DeclarationError) { MyApp::Devices::Serial.new_submodel(message_type: '/int32_t') }
    end

    def test_com_bus_type_options
      refute MyApp::Devices::Serial.lazy_dispatch?
      assert MyApp::Devices::Serial.override_policy?
      assert MyApp::Devices::Lazy.lazy_dispatch?
      refute MyApp::Devices::Lazy.override_policy?
    end

    DRIVERS = <<~RUBY
      require 'models/devices/things'
      Syskit.extend_model OroGen.stereo.Task do
        driver_for MyApp::Devices::Stereo, as: 'stereo'
        driver_for MyApp::Devices::Camera, as: 'left', slave_of: 'stereo', 'image' => 'left_image'
        provides MyApp::Rate, as: 'rate', slave_of: 'stereo'
        driver_for MyApp::Devices::Serial, as: 'serial'
        provides MyApp::Pose, as: 'pose'
      end
    RUBY

    STEREO = "name 'stereo'\ntask_context 'Task' do\n  output_port 'left_image', '/double'\nend\n"

    def load_drivers(extension = DRIVERS)
      camera = "module MyApp\n  module Devices\n    Camera.output_port 'image', '/double'\n  end\nend\n"
      root = my_app(nil, 'models/devices/things.rb' => MODELS + camera, 'models/orogen/stereo.orogen' => STEREO,
                         'models/orogen/stereo.rb' => extension)
      @loaded_apps.pop.unload
      load_app(root, everything: true, problems: true)
    end

    def test_driver_services_of_a_task_model
      app = load_drivers
      assert_empty app.problems, app.problems.map { |e| e.report(app.root) }.join("\n")
      task = OroGen.stereo.Task
      assert_equal %w[stereo serial], task.each_master_driver_service.map(&:name)
      assert_equal %w[serial], task.each_com_bus_driver_service.map(&:name)
      assert_equal %w[left rate], task.each_slave_data_service('stereo').map(&:name)
      assert_equal %w[stereo.left stereo.rate], task.each_slave_data_service(task.find_data_service('stereo'))
                                                    .map(&:full_name)
    end

    def test_a_slave_service_is_named_after_its_master
      load_drivers
      task = OroGen.stereo.Task
      left = task.find_data_service('stereo.left')
      assert_equal task.find_data_service('stereo'), left.master
      refute left.master?
      assert_equal({ 'image' => 'left_image' }, left.port_mappings)
      assert_equal %w[stereo stereo.left stereo.rate serial pose], task.each_data_service.map(&:full_name)
      assert_equal [MyApp::Devices::Stereo, MyApp::Devices::Serial], task.driven_device_models
    end

    def test_slave_of_an_unknown_service
      app = load_drivers("require 'models/devices/things'\nSyskit.extend_model OroGen.stereo.Task do\n  " \
                         "driver_for MyApp::Devices::Stereo, as: 'stereo'\n  " \
                         "provides MyApp::Rate, as: 'rate', slave_of: 'stero'\nend\n")
      assert_reported app.problems.first, /slave_of: 'stero' names no service of stereo::Task \(did you mean 'stereo'/,
                      at: 'models/orogen/stereo.rb:4', hint: /services: stereo/, root: app.root
    end
  end
end
