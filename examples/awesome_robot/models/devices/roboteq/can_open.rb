module AwesomeRobot
  module Devices
    module Roboteq
      # Roboteq motor controllers driven over CANOpen.
      device_type 'CANOpen'
    end
  end
end
