module AwesomeRobot
  module Devices
    module Roboteq
      # Roboteq motor controllers driven over CANOpen.
      device_type 'CANOpen' do
        input_port 'speed_command', '/double'
      end
    end
  end
end
