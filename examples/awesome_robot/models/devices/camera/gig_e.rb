module AwesomeRobot
  module Devices
    module Camera
      # Cameras on Gigabit Ethernet (GigE Vision).
      device_type 'GigE' do
        output_port 'frame', '/base/samples/frame/Frame'
      end
    end
  end
end
