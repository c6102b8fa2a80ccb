# frozen_string_literal: true

require 'helper'

module Syskit
  # The seed's "Devices" section: device models, declarations, drivers and
  # several devices of one type, each snippet as written in a fixture app.
  class TestSeedDevices < Minitest::Test
    def test_a_device_declaration_creates_a_dev_action_on_the_top_level_profile
      app = load_app(fixture('seed', 'device_declaration'))
      profile = AwesomeRobot::Profiles::Base
      assert_equal 'AwesomeRobot::Profiles::Base', profile.name
      action = profile.gps_dev
      assert_equal 'gps', action.device.name
      assert_same AwesomeRobot::Devices::GPS::UBlox::F9, action.device.model
      assert_equal [profile.syskit_profile], app.profiles.values
    end

    def test_the_driver_loaded_after_the_profile_is_still_associated
      load_app(fixture('seed', 'device_declaration'))
      device = AwesomeRobot::Profiles::Base.gps_dev.device
      assert_same OroGen.gps_ublox.F9Task, device.driver_model.component_model
    end

    def test_the_device_model_file_follows_the_naming_convention
      load_app(fixture('seed', 'device_declaration'))
      model = AwesomeRobot::Devices::GPS::UBlox::F9
      assert model.fullfills?(Syskit::Device)
      assert_equal fixture('seed', 'device_declaration', 'models', 'devices', 'gps', 'ublox', 'f9.rb'),
                   model.declared_at.path
    end

    def test_driver_for_associates_the_device_and_defines_the_dev_argument
      load_app(fixture('seed', 'drivers'))
      task_model = OroGen.gps_ublox.F9Task
      srv = task_model.find_service('f9')
      assert_same MyApp::Devices::GPS::Ublox::F9, srv.driven_device_model
      assert task_model.method_defined?(:f9_dev)
      assert_equal [MyApp::Devices::GPS::Ublox::F9], task_model.driven_device_models
    end

    def test_association_between_driver_and_device_names_the_argument_after_the_service
      load_app(fixture('seed', 'drivers'))
      assert OroGen.gps_ublox.Task.method_defined?(:f9p_dev)
      device = MyApp::Profiles::Live::Base.gps_dev.device
      task = OroGen.gps_ublox.Task.new(f9p_dev: device)
      assert_same device, task.f9p_dev
    end

    def test_using_chooses_among_several_drivers
      load_app(fixture('seed', 'drivers'))
      device = MyApp::Profiles::Live::Base.gps_dev.device
      assert_same OroGen.gps_ublox.F9Task, device.driver_model.component_model
    end

    def test_multiple_devices_of_one_type_get_their_deployment_and_configuration
      app = load_app(fixture('seed', 'cameras'))
      plan = Network::Generator.plan_profile(app, MyApp::Profiles::Base.syskit_profile).plan
      forward = plan.find_task('forward_camera')
      aft = plan.find_task('aft_camera')
      assert_equal 'forward_camera', forward.deployment
      assert_equal %w[default forward], forward.conf
      assert_equal({ 'exposure' => 5000, 'ip' => '10.40.50.50' }, forward.properties)
      assert_equal({ 'exposure' => 5000, 'ip' => '10.40.50.51' }, aft.properties)
      assert_equal ['aft_camera'], aft.devices
    end
  end
end
