require 'models/devices/n2k/bus'
require 'models/devices/n2k/fluid_level'

Syskit.extend_model OroGen.nmea2000.CANTask do
  driver_for AwesomeRobot::Devices::N2k::Bus, as: 'n2k'

  def configure
    super

    properties.devices = each_declared_attached_device.map do |dev|
      Types.nmea2000.Device.new(dev.name, dev.model.pgn)
    end
  end

  stub do
    devices.each do |dev|
      create_output_port dev.name, Types.canbus.Message
    end
  end
end

Syskit.extend_model OroGen.nmea2000.FluidLevelTask do
  driver_for AwesomeRobot::Devices::N2k::FluidLevel, as: 'fluid_level'
end
