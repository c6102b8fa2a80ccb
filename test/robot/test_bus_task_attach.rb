# frozen_string_literal: true

require 'helper'

module Syskit
  # Syskit's +bus_task.attach(device_task)+: the bus driver task gets a
  # service per device it serves (an instance of its bus model's com_bus
  # dynamic service), on the ports network generation would give it.
  class TestBusTaskAttach < Minitest::Test
    def setup
      super
      load_app(write_app({}), robots: [], models: false)
      @mark = Models.defined_models.size
      @robot = Robot::RobotDefinition.new
      device_m = Device.new_submodel(name: 'Sonar')
      @bus_m = ComBus.new_submodel(name: 'Wire', message_type: '/double')
      @driver_m = TaskContext.new_submodel(name: 'SonarDriver') do
        input_port 'from_bus', '/double'
        output_port 'to_bus', '/double'
        driver_for device_m, as: 'sonar'
      end
      @device_m = device_m
    end

    # The bus (driven by +model+) and the device attached to it.
    def declare(model, **attachment)
      @bus = @robot.com_bus(@bus_m, as: 'wire0', using: model)
      @device = @robot.device(@device_m, as: 'front').attach_to(@bus, **attachment)
    end

    def teardown
      Models.clear_defined_since(@mark)
      super
    end

    def bus_driver(&block)
      bus_m = @bus_m
      TaskContext.new_submodel(name: 'WireDriver') do
        driver_for bus_m, as: 'wire'
        instance_eval(&block)
      end
    end

    def test_a_bus_driver_has_the_com_bus_dynamic_service
      model = bus_driver { dynamic_output_port(/^\w+$/, '/double') }
      declare(model)
      assert_equal 'com_bus', @bus_m.dynamic_service_name
      assert_same @bus_m::BusBaseSrv, model.find_dynamic_service('com_bus').service_model
    end

    def test_attach_gives_the_bus_task_a_service_on_per_device_ports
      model = bus_driver do
        dynamic_output_port(/^\w+$/, '/double')
        dynamic_input_port(/^w\w+$/, '/double')
      end
      declare(model)
      bus_task = model.new(wire_dev: @bus)
      assert_equal [@device], bus_task.attach(@driver_m.new(sonar_dev: @device))
      srv = bus_task.front_srv
      assert_same @bus_m::BusSrv, srv.model.model
      assert_equal({ 'from_bus' => 'front', 'to_bus' => 'wfront' }, srv.model.port_mappings_for_task)
      assert_equal [@device], bus_task.each_attached_device.to_a
      refute model.find_data_service('front'), 'the model itself is left as it is'
    end

    def test_attach_maps_a_shared_input_of_the_bus_driver
      bus_m = @bus_m
      model = bus_driver do
        input_port 'in', '/double'
        dynamic_output_port(/^\w+$/, '/double')
        provides bus_m::BusInSrv, as: 'to_bus'
      end
      declare(model)
      bus_task = model.new(wire_dev: @bus)
      bus_task.attach(@driver_m.new(sonar_dev: @device))
      assert_equal({ 'from_bus' => 'front', 'to_bus' => 'in' }, bus_task.front_srv.model.port_mappings_for_task)
    end

    def test_attach_uses_a_shared_input_and_the_direction_of_the_device
      bus_m = @bus_m
      model = bus_driver do
        input_port 'in', '/double'
        dynamic_output_port(/^\w+$/, '/double')
        provides bus_m::BusInSrv, as: 'to_bus'
      end
      declare(model, client_to_bus: false)
      bus_task = model.new(wire_dev: @bus)
      bus_task.attach(@driver_m.new(sonar_dev: @device))
      srv = bus_task.front_srv
      assert_same @bus_m::BusOutSrv, srv.model.model
      assert_equal({ 'from_bus' => 'front' }, srv.model.port_mappings_for_task)
    end

    def test_the_com_bus_service_needs_both_directions
      model = bus_driver { dynamic_output_port(/^\w+$/, '/double') }
      declare(model)
      error = assert_raises(ArgumentError) do
        model.new.require_dynamic_service('com_bus', as: 'front', bus_to_client: true)
      end
      assert_match(/needs bus_to_client: and client_to_bus:/, error.message)
      assert_raises(ArgumentError) do
        model.new.require_dynamic_service('com_bus', as: 'front', bus_to_client: false, client_to_bus: false)
      end
    end

    def test_attach_ignores_devices_of_other_buses
      model = bus_driver { dynamic_output_port(/^\w+$/, '/double') }
      declare(model)
      other = @robot.com_bus(@bus_m, as: 'wire1', using: model)
      bus_task = model.new(wire_dev: other)
      assert_empty bus_task.attach(@driver_m.new(sonar_dev: @device))
      refute bus_task.respond_to?(:front_srv)
    end
  end
end
