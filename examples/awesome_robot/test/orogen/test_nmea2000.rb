require 'syskit/test'

module AwesomeRobot
  describe OroGen.nmea2000.CANTask do
    it 'creates one output per device, named after it, from the PGN of its model' do
      bus = syskit_stub_com_bus(Devices::N2k::Bus, driver: OroGen.nmea2000.CANTask)
      dev = syskit_stub_attached_device(bus, client_to_bus: false, base_model: Devices::N2k::Device)
      dev.model.pgn 127_505
      syskit_stub_deploy_and_configure(dev)
      bus_task, = task.each_child.first

      assert_equal [Types.nmea2000.Device.new(dev.name, 127_505)], bus_task.properties.devices
      assert bus_task.find_port(dev.name)
    end
  end
end
