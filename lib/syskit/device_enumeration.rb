# frozen_string_literal: true

module Syskit
  # Enumerating +devices+ (master devices and buses) and their slaves, under
  # Syskit's names, for whatever has devices: a robot (Robot::RobotLookups)
  # and a driver task (DeviceLookups).
  module DeviceEnumeration
    # Enumerates the devices and buses themselves.
    def each_master_device(&)
      devices.each(&)
    end

    # Enumerates the slave devices of each device, master by master.
    def each_slave_device(&block)
      return enum_for(__method__) unless block

      each_master_device { |device| device.each_slave(&block) }
    end
  end
end
