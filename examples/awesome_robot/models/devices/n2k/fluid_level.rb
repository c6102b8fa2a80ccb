require 'awesome_robot/models/devices/n2k/device'

module AwesomeRobot
  module Devices
    module N2k
      # Tank fluid level sensors.
      device_type 'FluidLevel', parent: Device do
        pgn 127_505
      end
    end
  end
end
