# frozen_string_literal: true

require 'helper'

module Syskit
  # Lookups that bundles and tests write on task models and their
  # services, as Syskit's component and bound data service models answer
  # them: ports by direction, services by model, a service's ports as the
  # task ports behind them, slave services from their master.
  class TestServiceLookups < Minitest::Test
    FILES = {
      'models/devices/things.rb' => <<~RUBY,
        module MyApp
          data_service_type('Pose') { output_port 'pose', '/double' }
          data_service_type('Cmd') { input_port 'cmd', '/double' }
          module Devices
            device_type 'Gps' do
              output_port 'position', '/double'
              provides Pose, 'pose' => 'position'
            end
            device_type('Camera') { output_port 'image', '/int32_t' }
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
      RUBY
      'models/orogen/nav.rb' => <<~RUBY
        Syskit.extend_model OroGen.nav.GpsTask do
          driver_for MyApp::Devices::Gps, as: 'gps'
          provides MyApp::Cmd, as: 'cmd'
        end
        Syskit.extend_model OroGen.nav.StereoTask do
          driver_for MyApp::Devices::Camera, as: 'stereo', 'image' => 'left'
          driver_for MyApp::Devices::Camera, as: 'left', slave_of: 'stereo', 'image' => 'left'
          driver_for MyApp::Devices::Camera, as: 'right', slave_of: 'stereo', 'image' => 'right'
        end
      RUBY
    }.freeze

    def setup
      super
      @root = my_app(nil, FILES)
      load_app(@root, everything: true)
      @gps_task = OroGen.nav.GpsTask
      @stereo_task = OroGen.nav.StereoTask
    end

    def test_ports_of_a_task_model_by_direction
      assert_equal %w[fix state], @gps_task.each_output_port.map(&:name)
      assert_equal %w[cmd], @gps_task.each_input_port.map(&:name)
      assert @gps_task.has_output_port?('fix')
      refute @gps_task.has_output_port?('cmd')
      assert @gps_task.has_input_port?('cmd')
      refute @gps_task.has_input_port?('nope')
    end

    def test_a_service_by_its_model
      srv = @gps_task.find_data_service_from_type(MyApp::Pose)
      assert_equal 'gps', srv.full_name
      assert_equal MyApp::Pose, srv.model, 'seen through the model asked for'
      assert_equal 'pose', srv.pose_port.name
      assert_equal 'fix', srv.pose_port.to_component_port.name
      assert_nil @stereo_task.find_data_service_from_type(MyApp::Pose)
      assert_equal @gps_task.cmd_srv, @gps_task.find_data_service_from_type(MyApp::Cmd)
    end

    def test_several_services_of_the_model_asked_for_are_ambiguous
      error = assert_raises(AmbiguousServiceSelection) do
        @stereo_task.find_data_service_from_type(MyApp::Devices::Camera)
      end
      assert_match 'nav::StereoTask has several services of type MyApp::Devices::Camera: stereo, stereo.left, ' \
                   'stereo.right', error.message
      assert_match "find_data_service('stereo')", error.hint
      assert_equal %w[stereo stereo.left stereo.right],
                   @stereo_task.find_all_data_services_from_type(MyApp::Devices::Camera).map(&:full_name)
      assert_empty @stereo_task.find_all_data_services_from_type(MyApp::Cmd)
    end

    def test_a_service_gives_the_task_ports_behind_its_ports
      srv = @gps_task.gps_srv
      assert_equal @gps_task, srv.component_model
      assert_equal [MyApp::Devices::Gps], srv.fullfilled_model
      assert_same srv.find_output_port('position'), srv.position_port, 'one port model per service port'
      assert_same srv, srv.position_port.component_model
      assert_equal @gps_task.fix_port, srv.position_port.to_component_port
      assert_same @gps_task.find_port('fix'), srv.find_port('position'), 'the declaration behind it'
      assert_nil srv.find_port('fix'), 'a port of the task, not of the service'
      assert_equal %w[position], srv.each_output_port.map(&:name)
      assert_empty srv.each_input_port.to_a
    end

    def test_the_port_models_of_a_promoted_service_are_its_own
      srv = @gps_task.gps_srv
      srv.position_port
      sub = @gps_task.new_submodel
      assert_equal sub, srv.attach(sub).position_port.to_component_port.component_model
    end

    def test_a_service_maps_its_ports_to_the_task_ports
      srv = @gps_task.gps_srv
      assert_equal({ 'position' => 'fix' }, srv.port_mappings_for_task)
      assert_equal({ 'pose' => 'fix' }, srv.port_mappings_for(MyApp::Pose))
      assert_equal 'position', srv.find_port_for_task_port('fix').name
      assert_nil srv.find_port_for_task_port('cmd')
      assert_same srv.position_port, srv.find_port_for_task_port('fix')
      assert_equal @gps_task.fix_port, srv.self_port_to_component_port('position')
    end

    def test_a_service_seen_through_a_model_it_provides
      pose = @gps_task.gps_srv.as(MyApp::Pose)
      assert_equal 'fix', pose.pose_port.to_component_port.name
      assert_equal({ 'pose' => 'fix' }, pose.port_mappings_for_task)
      refute_equal @gps_task.gps_srv, pose
      assert pose.same_service?(@gps_task.gps_srv)
      refute pose.same_service?(@gps_task.cmd_srv)
      error = assert_raises(DeclarationError) { @gps_task.gps_srv.as(MyApp::Cmd) }
      assert_match "service 'gps' (MyApp::Devices::Gps) of nav::GpsTask does not provide MyApp::Cmd", error.message
    end

    def test_slave_services_from_their_master
      stereo = @stereo_task.stereo_srv
      assert_same @stereo_task.find_data_service('stereo.left'), stereo.left_srv
      assert_same stereo.right_srv, stereo.find_data_service('right')
      assert_nil stereo.find_data_service('stereo')
      assert_equal %w[stereo.left stereo.right], stereo.each_slave_data_service.map(&:full_name)
      assert_equal 'right', stereo.right_srv.image_port.to_component_port.name
    end

    def test_a_submodel_has_the_services_of_its_parent_as_its_own
      sub = @stereo_task.new_submodel
      srv = sub.stereo_srv
      assert_equal sub, srv.component_model
      assert_same @stereo_task.stereo_srv, srv.demoted
      assert srv.same_service?(@stereo_task.stereo_srv)
      refute_equal @stereo_task.stereo_srv, srv, 'services of two models'
      assert_equal sub, srv.left_srv.component_model
      assert_same srv, srv.left_srv.master
      assert_same sub.find_data_service('stereo.left'), srv.left_srv
      assert_equal srv, @stereo_task.stereo_srv.attach(sub)
      assert_raises(DeclarationError) { sub.stereo_srv.attach(@stereo_task) }
    end

    def test_bind_checks_that_a_model_stands_for_another
      assert_equal @gps_task, @gps_task.bind(@gps_task)
      assert_equal @gps_task.gps_srv, @gps_task.try_bind(@gps_task.gps_srv)
      assert_nil @gps_task.try_bind(@stereo_task)
      error = assert_raises(DeclarationError) { @gps_task.bind(@stereo_task) }
      assert_match 'cannot bind nav::GpsTask to nav::StereoTask', error.message
    end

    def test_bind_takes_a_task_of_the_model_or_of_a_submodel
      task = @gps_task.new_submodel.new
      assert_same task, @gps_task.bind(task)
      assert_nil @stereo_task.try_bind(task)
      assert_nil @gps_task.try_bind(Object.new)
    end

    def test_resolve_is_bind_under_its_deprecated_name
      task = @gps_task.new
      level = ENV.fetch('SYSKIT_LOG', nil)
      ENV['SYSKIT_LOG'] = 'debug'
      _, err = capture_io do
        assert_same task, @gps_task.resolve(task)
        assert_nil @stereo_task.try_resolve(task)
      end
      assert_match(/resolve is deprecated, use Models::Component#bind/, err)
      assert_match(/try_resolve is deprecated, use Models::Component#try_bind/, err)
    ensure
      ENV['SYSKIT_LOG'] = level
    end
  end
end
