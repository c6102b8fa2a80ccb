module AwesomeRobot
  module Devices
    module Temperature
      # A temperature probe that reports on a CAN bus.
      device_type 'CANSensor' do
        output_port 'temperature', '/double'
      end
    end
  end
end
