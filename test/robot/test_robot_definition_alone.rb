# frozen_string_literal: true

require 'helper'

module Syskit
  # A robot made alone (Robot::RobotDefinition), as Syskit's tests make
  # one: each device gets its driver as it is declared, devices are found
  # by name, and bus attachments choose their client services at once.
  class TestRobotDefinitionAlone < Minitest::Test
    def setup
      super
      load_app(write_app({}), robots: [], models: false)
      @mark = Models.defined_models.size
      @robot = Robot::RobotDefinition.new
      @device_m = Device.new_submodel(name: 'Sonar')
      device_m = @device_m
      @driver_m = TaskContext.new_submodel(name: 'SonarDriver') { driver_for device_m, as: 'sonar' }
    end

    def teardown
      Models.clear_defined_since(@mark)
      super
    end

    def test_a_device_gets_the_only_driver_made_in_ruby
      device = @robot.device(@device_m, as: 'front')
      assert_same @driver_m, device.driver_model.component_model
    end

    # As in Syskit, a device's driver_model is the driver's service for it.
    def test_the_driver_model_of_a_device_is_the_drivers_service
      device = @robot.device(@device_m, as: 'front')
      assert_same @driver_m.sonar_srv, device.driver_model
      assert_equal({ sonar_dev: device }, device.driver_arguments)
    end

    def test_a_profiles_device_action_is_the_drivers_service_bound_to_the_device
      profile = Actions::Profile.new('Probe')
      device = profile.robot.device(@device_m, as: 'front')
      assert_same @driver_m.sonar_srv, profile.front_dev.model
      assert_same device, profile.front_dev.arguments[:sonar_dev]
    end

    def test_using_a_task_that_does_not_drive_the_device_is_an_argument_error
      other = TaskContext.new_submodel(name: 'Other')
      error = assert_raises(ArgumentError) { @robot.device(@device_m, as: 'front', using: other) }
      assert_match(/Other does not drive Sonar/, error.message)
      refute @robot.has_device?('front')
    end

    def test_the_requirements_of_a_device_bind_its_driver_to_it
      device = @robot.device(@device_m, as: 'front')
      requirements = device.requirements
      assert_equal [@driver_m], requirements.models
      assert_same device, requirements.arguments[:sonar_dev]
    end

    def test_devices_are_found_by_name_slaves_by_their_full_name
      slave_m = DataService.new_submodel(name: 'Beam')
      @driver_m.provides slave_m, as: 'beam', slave_of: 'sonar'
      device = @robot.device(@device_m, as: 'front')
      assert_same device, @robot.devices['front']
      assert_same device.beam_dev, @robot.devices['front.beam']
      assert_equal [device], @robot.each_master_device.to_a
      assert_equal ['front'], @robot.device_names
    end

    def test_devices_are_equal_by_robot_and_name
      device = @robot.device(@device_m, as: 'front')
      other_robot = Robot::RobotDefinition.new
      refute_equal device, other_robot.device(@device_m, as: 'front')
      refute_equal device, @robot.device(@device_m, as: 'back')
      assert_equal device, @robot.find_device('front')
      assert_equal device.hash, @robot.find_device('front').hash
    end

    def test_slaves_are_equal_by_master_and_name
      slave_m = DataService.new_submodel(name: 'Beam')
      @driver_m.provides slave_m, as: 'beam', slave_of: 'sonar'
      @driver_m.provides slave_m, as: 'echo', slave_of: 'sonar'
      front = @robot.device(@device_m, as: 'front')
      back = @robot.device(@device_m, as: 'back')
      assert_equal front.slave('beam'), front.beam_dev
      refute_equal front.beam_dev, front.echo_dev
      refute_equal front.beam_dev, back.beam_dev
    end

    def bus_setup(ports: true)
      if ports
        @driver_m.input_port 'frames_in', '/double'
        @driver_m.output_port 'frames_out', '/double'
      end
      @bus_m = ComBus.new_submodel(name: 'Wire', message_type: '/double')
      bus_m = @bus_m
      TaskContext.new_submodel(name: 'WireDriver') { driver_for bus_m, as: 'wire' }
      @bus = @robot.com_bus(@bus_m, as: 'wire0')
      @device = @robot.device(@device_m, as: 'front')
    end

    def test_attaching_chooses_the_client_services_of_the_driver
      bus_setup
      @driver_m.provides @bus_m.client_srv, as: 'link'
      @device.attach_to('wire0')
      assert_equal @driver_m.link_srv.as(@bus_m.client_in_srv), @device.combus_client_in_srv
      assert_equal @driver_m.link_srv.as(@bus_m.client_out_srv), @device.combus_client_out_srv
    end

    def test_a_direction_the_device_does_not_use_has_no_client_service
      bus_setup
      @driver_m.provides @bus_m.client_in_srv, as: 'bus_in'
      @device.attach_to(@bus, client_to_bus: false)
      assert_equal @driver_m.bus_in_srv, @device.combus_client_in_srv
      assert_nil @device.combus_client_out_srv
    end

    def test_several_client_services_need_a_name
      bus_setup
      @driver_m.provides @bus_m.client_in_srv, as: 'a_in'
      @driver_m.provides @bus_m.client_in_srv, as: 'b_in'
      error = assert_raises(ArgumentError) { @device.attach_to(@bus, client_to_bus: false) }
      assert_match(/provides several bus client services .*: a_in, b_in/, error.message)
      assert_equal "#{File.expand_path(__FILE__)}:#{__LINE__ - 2}", error.location.to_s
    end

    def test_a_named_client_service_disambiguates
      bus_setup
      @driver_m.provides @bus_m.client_in_srv, as: 'a_in'
      @driver_m.provides @bus_m.client_in_srv, as: 'b_in'
      @device.attach_to(@bus, client_to_bus: false, bus_to_client: 'b_in')
      assert_equal @driver_m.b_in_srv, @device.combus_client_in_srv
      assert_raises(ArgumentError) { @device.resolve_combus_client_srv(@bus_m.client_in_srv, 'c_in', @bus, 'x') }
    end

    def test_a_driver_without_a_way_to_the_bus_cannot_be_attached
      bus_setup(ports: false)
      error = assert_raises(ArgumentError) { @device.attach_to(@bus) }
      assert_match(/SonarDriver, the driver of device 'front', has no Wire::ClientInSrv service/, error.message)
      refute @device.attached?
    end

    def test_a_single_port_of_the_message_type_is_a_way_to_the_bus
      bus_setup
      @device.attach_to(@bus, client_to_bus: false)
      assert_nil @device.combus_client_in_srv
    end
  end
end
