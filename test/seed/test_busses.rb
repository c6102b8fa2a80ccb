# frozen_string_literal: true

require 'helper'

module Syskit
  # The seed's "Communication Busses" section.
  class TestSeedBusses < Minitest::Test
    def plan_of(app_dir, profile)
      app = load_app(fixture('seed', *app_dir))
      Network::Generator.plan_profile(app, profile.call.syskit_profile).plan
    end

    def conn(connection)
      ["#{connection.from.task}.#{connection.from.port}", "#{connection.to.task}.#{connection.to.port}",
       connection.policy]
    end

    def test_using_an_existing_bus_in_a_module_profile
      load_app(fixture('seed', 'can_bus'))
      profile = MyApp::Profiles::Base
      bus = profile.can0_dev.device
      sensor = profile.temperature_sensor_dev.device
      assert bus.com_bus?
      assert_same bus, sensor.bus
      assert_equal [0x1234, 0xffff], sensor.can_id
      assert_same MyApp::Devices::TemperatureSensor, sensor.model
      assert_same OroGen.can_temperature_sensor.Task, sensor.driver_model.component_model
    end

    # "configured to create a single output port named temperature_sensor on
    # which CAN messages which match the can_id filter are routed; connected
    # that output port to the device's input port; connected the device's
    # output to the bus component's input, shared for all attached devices;
    # the CAN component is started before the attached devices are configured"
    def test_the_generated_can_network_is_the_one_the_seed_describes
      plan = plan_of('can_bus', -> { MyApp::Profiles::Base })
      can0 = plan.find_task('can0')
      assert_equal 'canbus::Task', can0.model
      # As Rock's canbus component is: a watch per device, at configure time.
      assert_equal [['watch', ['temperature_sensor', 0x1234, 0xffff], %w[name id mask]]], can0.operations.map(&:to_a)
      port = can0.ports.find { |p| p.name == 'temperature_sensor' }
      assert_equal ['output', '/canbus/Message', true], [port.direction, port.type, port.dynamic]

      assert_equal([['can0.temperature_sensor', 'temperature_sensor.can_in', { 'type' => 'buffer', 'size' => 20 }],
                    ['temperature_sensor.can_out', 'can0.in', { 'type' => 'buffer', 'size' => 20 }]],
                   plan.connections.map { |c| conn(c) })
      steps = plan.order.map { |s| "#{s.step} #{s.task}" }
      assert_equal ['configure can0', 'start can0', 'configure temperature_sensor', 'start temperature_sensor'], steps
      assert_equal ['can0'], plan.find_task('temperature_sensor').depends_on
    end

    def test_read_only_device_gets_only_the_bus_to_device_connection
      plan = plan_of('read_only', -> { MyApp::Profiles::Base })
      assert_equal([['can0.temperature_sensor', 'temperature_sensor.can_in', { 'type' => 'buffer', 'size' => 20 }]],
                   plan.connections.map { |c| conn(c) })
    end

    def test_write_only_device_gets_only_the_device_to_bus_connection
      plan = plan_of('write_only', -> { MyApp::Profiles::Base })
      assert_equal([['sync.can_out', 'can0.in', { 'type' => 'buffer', 'size' => 20 }]],
                   plan.connections.map { |c| conn(c) })
      refute(plan.find_task('can0').ports.any? { |p| p.name == 'sync' })
      assert_equal [], plan.find_task('can0').operations
    end

    def test_a_bus_defined_from_the_generated_template
      load_app(fixture('seed', 'new_bus'))
      bus = MyApp::Devices::Bus::CAN
      assert_same ::Types.canbus.Message, bus.message_type
      assert_equal 'MyApp::Devices::Bus::CAN::BusSrv', bus.bus_srv.name
      assert bus.fullfills?(Syskit::ComBus)
    end

    def test_the_seven_bus_services_and_their_ports
      load_app(fixture('seed', 'new_bus'))
      bus = MyApp::Devices::Bus::CAN
      ports = Models::ComBusModel::SERVICES.to_h do |name|
        srv = bus.const_get(name)
        [name, srv.ports.values.map { |p| [p.name, p.direction, p.type.name] }.sort]
      end
      msg = '/canbus/Message'
      assert_equal({ 'BusBaseSrv' => [], 'BusSrv' => [['from_bus', :output, msg], ['to_bus', :input, msg]],
                     'BusInSrv' => [['to_bus', :input, msg]], 'BusOutSrv' => [['from_bus', :output, msg]],
                     'ClientSrv' => [['from_bus', :input, msg], ['to_bus', :output, msg]],
                     'ClientInSrv' => [['from_bus', :input, msg]], 'ClientOutSrv' => [['to_bus', :output, msg]] },
                   ports)
      assert bus::BusSrv.fullfills?(bus::BusInSrv)
      assert bus::ClientSrv.fullfills?(bus::ClientOutSrv)
    end

    def test_extend_attached_device_configuration_adds_methods_to_attached_devices
      load_app(fixture('seed', 'new_bus'))
      robot = Robot::Definition.new(nil)
      bus = robot.add_device(Robot::ComBus, MyApp::Devices::Bus::CANWithID, 'bus', using: nil, options: {},
                                                                                   location: nil)
      dev = robot.add_device(Robot::MasterDeviceInstance, MyApp::Devices::ECU::Engine, 'engine',
                             using: nil, options: {}, location: nil, bus: bus)
      assert_nil dev.can_id(1, 2)
      free = robot.add_device(Robot::MasterDeviceInstance, MyApp::Devices::ECU::Engine, 'free',
                              using: nil, options: {}, location: nil)
      refute_respond_to free, :can_id
      assert_includes MyApp::Devices::Bus::CANWithID.attached_device_configuration_module.instance_methods, :can_id
    end

    def test_clear_model_forgets_ports_and_provided_models
      load_app(fixture('seed', 'new_bus'))
      bus = ComBus.new_submodel(message_type: '/double')
      bus.clear_model
      assert_equal [bus], bus.fullfilled_models
      bus.provides ComBus
      assert bus.fullfills?(ComBus)
      device = Device.new_submodel { output_port 'out', '/double' }
      device.clear_model
      assert_empty device.ports
      refute device.fullfills?(Device)
    end

    def test_dsl_attribute_as_the_seed_shows
      load_app(fixture('seed', 'new_bus'))
      robot = Robot::Definition.new(nil)
      bus = robot.add_device(Robot::ComBus, MyApp::Devices::Bus::Doubling, 'bus', using: nil, options: {},
                                                                                  location: nil)
      device = robot.add_device(Robot::MasterDeviceInstance, MyApp::Devices::ECU::Engine, 'engine',
                                using: nil, options: {}, location: nil, bus: bus)
      assert_nil device.can_id
      assert_same device, device.can_id(1, 2)
      assert_equal [2, 4], device.can_id
    end

    def test_non_demultiplexing_bus_shares_its_ports_and_devices_filter_themselves
      plan = plan_of('non_demux', -> { MyApp::Profiles::Base })
      assert_equal([['can0.out', 'left_motor.can_in', { 'type' => 'data' }],
                    ['can0.out', 'right_motor.can_in', { 'type' => 'data' }],
                    ['left_motor.can_out', 'can0.in', { 'type' => 'buffer', 'size' => 20 }],
                    ['right_motor.can_out', 'can0.in', { 'type' => 'buffer', 'size' => 20 }]],
                   plan.connections.map { |c| conn(c) })
      assert_equal({ 'can_id' => 0x181, 'can_mask' => 0x7ff }, plan.find_task('left_motor').properties)
      assert_equal({ 'can_id' => 0x182, 'can_mask' => 0x7ff }, plan.find_task('right_motor').properties)
    end

    def test_demultiplexing_bus_gets_per_device_ports_from_its_configure_and_stub
      plan = plan_of('demux', -> { MyApp::Profiles::Base })
      can0 = plan.find_task('can0')
      assert_equal [{ 'name' => 'temperature_sensor', 'id' => 0x1234, 'mask' => 0xffff }], can0.properties['devices']
      assert_equal([%w[temperature_sensor output], %w[wtemperature_sensor input]],
                   can0.ports.map { |p| [p.name, p.direction] })
      assert_equal([['can0.temperature_sensor', 'temperature_sensor.can_in', { 'type' => 'buffer', 'size' => 20 }],
                    ['temperature_sensor.can_out', 'can0.wtemperature_sensor', { 'type' => 'buffer', 'size' => 20 }]],
                   plan.connections.map { |c| conn(c) })
    end

    def test_shared_input_port_replaces_the_per_device_inputs
      plan = plan_of('shared_input', -> { MyApp::Profiles::Base })
      assert_equal %w[msg_in temperature_sensor], plan.find_task('can0').ports.map(&:name)
      assert_equal(['can0.msg_in'],
                   plan.connections_from('temperature_sensor').map { |c| "#{c.to.task}.#{c.to.port}" })
    end

    def test_port_disambiguation_with_an_explicit_client_service
      plan = plan_of('disambiguation', -> { MyApp::Profiles::Base })
      assert_equal([['bus0.from_bus', 'multiport.can_in', { 'type' => 'data' }],
                    ['multiport.can_out', 'bus0.to_bus', { 'type' => 'buffer', 'size' => 20 }]],
                   plan.connections.map { |c| conn(c) })
      srv = OroGen.project.Task.find_service('client_in')
      assert_equal({ 'from_bus' => 'can_in', 'to_bus' => 'can_out' }, srv.port_mappings)
    end

    def test_device_model_level_information_is_available_at_configure_time
      app = load_app(fixture('seed', 'nmea2000', 'seabots'))
      assert_equal 127_505, Seabots::Devices::N2k::FluidLevel.pgn
      assert_kind_of Seabots::Devices::N2k::DeviceModel, Seabots::Devices::N2k::FluidLevel
      result = Network::Generator.plan_profile(app, Seabots::Profiles::Base.syskit_profile)
      bus_task = result.task_for(Seabots::Profiles::Base.n2k_dev)
      assert_equal [['fuel', 127_505]], bus_task.pgns
    end
  end
end
