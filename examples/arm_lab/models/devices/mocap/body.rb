require 'models/services/pose'

module ArmLab
  module Devices
    module Mocap
      # A rigid body the motion-capture system tracks (a set of markers).
      device_type 'Body' do
        provides Services::Pose
      end
    end
  end
end
