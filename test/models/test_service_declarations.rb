# frozen_string_literal: true

require 'helper'

module Syskit
  # Service declarations Syskit accepts or refuses beyond port mappings: a
  # subclass of a driver re-declaring its parent's service with a more
  # specific device, the ports a dynamic service needs, and the task
  # arguments its instances declare.
  class TestServiceDeclarations < Minitest::Test
    DEVICES = <<~RUBY
      module MyApp
        data_service_type('Cmd') { input_port 'cmd', '/double' }
        module Devices
          device_type('Gps') { output_port 'fix', '/double' }
          device_type('RtkGps') { provides Gps }
          device_type('Camera') { output_port 'image', '/int32_t' }
        end
      end
    RUBY

    ORO = <<~RUBY
      name 'gps'
      task_context 'Task' do
        output_port 'fix', '/double'
        dynamic_output_port(/\\w+_image/, '/int32_t')
      end
      task_context 'F9Task', subclasses: 'gps::Task' do
      end
    RUBY

    def app_with(extension)
      root = my_app(nil, 'models/devices/things.rb' => DEVICES, 'models/orogen/gps.orogen' => ORO,
                         'models/orogen/gps.rb' => extension)
      [root, load_app(root, problems: true, everything: true)]
    end

    def test_a_subclass_may_drive_a_more_specific_device_under_its_parents_service_name
      _, app = app_with(<<~RUBY)
        Syskit.extend_model(OroGen.gps.Task) { driver_for MyApp::Devices::Gps, as: 'gps' }
        Syskit.extend_model(OroGen.gps.F9Task) { driver_for MyApp::Devices::RtkGps, as: 'gps' }
      RUBY
      assert_empty app.errors
      assert_equal MyApp::Devices::RtkGps, OroGen.gps.F9Task.gps_srv.model
      assert_equal OroGen.gps.F9Task, OroGen.gps.F9Task.gps_srv.component_model
      assert_equal MyApp::Devices::Gps, OroGen.gps.Task.gps_srv.model, 'the parent keeps its own'
      assert_equal [OroGen.gps.F9Task.gps_srv], OroGen.gps.F9Task.each_data_service.to_a
    end

    def test_a_device_driven_through_an_inherited_service_is_driven_by_the_subclass
      extension = "Syskit.extend_model(OroGen.gps.Task) { driver_for MyApp::Devices::Gps }\n"
      root = my_app("device(MyApp::Devices::Gps, as: 'gps', using: OroGen.gps.F9Task.gps_srv)",
                    { 'models/devices/things.rb' => DEVICES, 'models/orogen/gps.orogen' => ORO,
                      'models/orogen/gps.rb' => extension }, libraries: %w[gps])
      load_app(root)
      device = MyApp::Profiles::Base.syskit_profile.robot.find_device('gps')
      assert_equal OroGen.gps.F9Task, device.driver_model.component_model
    end

    def test_a_subclass_cannot_replace_a_service_by_an_unrelated_one
      root, app = app_with(<<~RUBY)
        Syskit.extend_model(OroGen.gps.Task) { driver_for MyApp::Devices::RtkGps, as: 'gps' }
        Syskit.extend_model(OroGen.gps.F9Task) { driver_for MyApp::Devices::Gps, as: 'gps' }
      RUBY
      assert_equal 1, app.errors.size
      message = "MyApp::Devices::Gps cannot replace the service 'gps' (MyApp::Devices::RtkGps) of gps::Task " \
                'declared at models/orogen/gps.rb:1: it does not provide MyApp::Devices::RtkGps'
      assert_reported app.errors.first, message,
                      at: 'models/orogen/gps.rb:2', hint: /another name with as:/, root: root
    end

    def test_a_service_is_declared_once_per_model
      root, app = app_with(<<~RUBY)
        Syskit.extend_model OroGen.gps.Task do
          driver_for MyApp::Devices::Gps, as: 'gps'
          driver_for MyApp::Devices::RtkGps, as: 'gps'
        end
      RUBY
      assert_reported app.errors.first, /gps::Task already has a service 'gps'/,
                      at: 'models/orogen/gps.rb:3', root: root
    end

    # As in Syskit, a dynamic service is checked when an instance is made,
    # not where it is declared: real bundles declare services for every
    # control domain, some of which the task's version cannot serve.
    def test_a_dynamic_service_is_checked_when_an_instance_is_made
      root, app = app_with(<<~RUBY)
        Syskit.extend_model OroGen.gps.Task do
          dynamic_service MyApp::Cmd, as: 'commands' do
            provides MyApp::Cmd, 'cmd' => "\#{name}_cmd"
          end
        end
      RUBY
      assert_empty app.errors
      error = assert_raises(Syskit::Error) { OroGen.gps.Task.with_dynamic_service('commands', as: 'steer') }
      assert_reported error, %r{port 'steer_cmd', mapped to .*Cmd's input port 'cmd' \(/double\), does not exist},
                      at: 'models/orogen/gps.rb:3', hint: %r{an input port of type /double}, root: root
    end

    def test_the_block_of_a_dynamic_service_declares_task_arguments
      _, app = app_with(<<~RUBY)
        Syskit.extend_model OroGen.gps.Task do
          dynamic_service MyApp::Devices::Camera, as: 'cameras' do
            argument "\#{name}_frame", default: name
            driver_for MyApp::Devices::Camera, 'image' => "\#{name}_image"
          end
        end
      RUBY
      assert_empty app.errors
      task_m = OroGen.gps.Task.specialize
      task_m.require_dynamic_service('cameras', as: 'front')
      assert task_m.has_argument?(:front_frame)
      refute OroGen.gps.Task.has_argument?(:front_frame), 'the task model itself is unchanged'
      assert_equal({ front_frame: 'front' }, task_m.argument_defaults)
    end
  end
end
