require 'syskit/test'

module AwesomeRobot
  describe OroGen.canbus.Task do
    it 'watches the frames of every device that reads from the bus' do
      bus = syskit_stub_com_bus(CommonModels::Devices::Bus::CAN)
      reader = syskit_stub_attached_device(bus, as: 'reader').can_id(0x100, 0x7f0)
      syskit_stub_attached_device(bus, as: 'writer', bus_to_client: false).can_id(0x80, 0x7ff)
      syskit_stub_deploy_and_configure(reader)
      bus_task, = task.each_child.first

      assert_equal [['watch', ['reader', 0x100, 0x7f0]]], bus_task.operation_calls.map { |c| [c.name, c.arguments] }
      assert_equal ['reader'], bus_task.created_ports.keys
    end

    it 'refuses a reading device without a CAN filter' do
      bus = syskit_stub_com_bus(CommonModels::Devices::Bus::CAN)
      dev = syskit_stub_attached_device(bus)
      error = assert_raises(Syskit::ConfigurationError) { syskit_stub_deploy_and_configure(dev) }
      assert_match(/has no CAN filter/, error.message)
    end
  end
end
