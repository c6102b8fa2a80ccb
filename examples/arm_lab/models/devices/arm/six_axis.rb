require 'models/services/joints'

module ArmLab
  module Devices
    module Arm
      # A six-axis arm, its joints commanded in position.
      device_type 'SixAxis' do
        input_port 'joints_cmd', '/base/commands/Joints'
        output_port 'joints_status', '/base/samples/Joints'
        provides Services::JointsControlledSystem, 'command_in' => 'joints_cmd', 'status_out' => 'joints_status'
      end
    end
  end
end
