require 'models/services/position'

module AwesomeRobot
  module Devices
    module GPS
      module Ublox
        # Ublox's 9th generation GNSS receivers (F9P, F9R).
        device_type 'F9' do
          output_port 'pose_samples', '/base/samples/RigidBodyState'
          provides Services::Position, 'position_samples' => 'pose_samples'
        end
      end
    end
  end
end
