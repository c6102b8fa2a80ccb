require 'models/services/position'
require 'models/devices/roboteq/can_open'
using_task_library 'navigation'

module AwesomeRobot
  module Compositions
    # Drives the robot along its path: a position source feeds the path
    # follower, which commands the two wheel motors.
    class Drive < Syskit::Composition
      argument :max_speed, default: 1.0

      add Services::Position, as: 'position'
      add(OroGen.navigation.PathFollower, as: 'follower')
        .with_arguments(max_speed: from(:parent_task).max_speed)
      add Devices::Roboteq::CANOpen, as: 'left'
      add Devices::Roboteq::CANOpen, as: 'right'

      position_child.position_samples_port.connect_to follower_child.pose_port
      follower_child.left_speed_port.connect_to left_child.speed_command_port
      follower_child.right_speed_port.connect_to right_child.speed_command_port

      export follower_child.pose_port, as: 'pose'
    end
  end
end
