# Syskit integration of the bundled canbus::Task: it drives CAN buses, takes
# every device's frames on its shared 'in' port (BusInSrv) and creates one
# output port per device that reads from the bus.
Syskit.extend_model OroGen.canbus.Task do
  driver_for CommonModels::Devices::Bus::CAN, as: 'can'
  provides CommonModels::Devices::Bus::CAN::BusInSrv, as: 'bus_in'

  def configure
    super

    readers = each_declared_attached_device.select(&:bus_to_client?)
    properties.devices = readers.map do |dev|
      id, mask = dev.can_id
      unless id
        raise Syskit::ConfigurationError.new(
          "#{dev} is attached to #{can_dev} but has no CAN filter",
          location: dev.declared_at, hint: 'declare the frames it receives with .can_id(id, mask)'
        )
      end

      Types.canbus.Device.new(dev.name, id, mask)
    end
  end

  stub do
    devices.each do |dev|
      create_output_port dev.name, Types.canbus.Message
    end
  end
end
