require 'models/devices/arm/six_axis'
using_task_library 'arm_control'

module ArmLab
  module Compositions
    # Closes the loop between a joint controller and an arm: the
    # controller reads the arm's joints and commands them.
    class ArmControl < Syskit::Composition
      # Scales the controller's speed limits, from 0 (stopped) to 1.
      argument :speed_scale, default: 1.0

      add(Services::JointsController, as: 'controller')
        .with_arguments(speed_scale: from(:parent_task).speed_scale)
      add Devices::Arm::SixAxis, as: 'arm'

      arm_child.joints_status_port.connect_to controller_child.status_in_port
      # Every command counts: queue them rather than keep the last one.
      controller_child.command_out_port.connect_to arm_child.joints_cmd_port, type: :buffer, size: 10

      export arm_child.joints_status_port, as: 'status'
      provides Services::JointsStatus, as: 'status'

      # Slow and soft, to work next to people.
      conf 'gentle', controller_child => %w[default gentle]

      # A joint position controller holds the setpoint it is given.
      specialize controller_child => OroGen.arm_control.JointPositionController do
        export controller_child.setpoint_port
      end

      # A Cartesian controller moves the tool to a target pose.
      specialize controller_child => OroGen.arm_control.CartesianController do
        export controller_child.target_port
        export controller_child.obstacle_port
      end
    end
  end
end
