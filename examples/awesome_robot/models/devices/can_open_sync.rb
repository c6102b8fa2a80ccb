module AwesomeRobot
  module Devices
    # The CANOpen SYNC message generator: it only writes to the bus.
    device_type 'CANOpenSync'
  end
end
