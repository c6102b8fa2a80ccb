require 'syskit/test'

module AwesomeRobot
  describe OroGen.roboteq.Task do
    it 'filters the frames of its device itself' do
      bus = syskit_stub_com_bus(CommonModels::Devices::Bus::CAN)
      dev = syskit_stub_attached_device(bus)
            .can_id(0x181, 0x7ff)
      dev_task = syskit_stub_deploy_and_configure(dev)

      assert_equal 0x181, dev_task.properties.can_id
      assert_equal 0x7ff, dev_task.properties.can_mask
    end
  end
end
