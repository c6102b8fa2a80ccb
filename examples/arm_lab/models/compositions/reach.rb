require 'models/compositions/arm_control'
require 'models/services/pose'

module ArmLab
  module Compositions
    # Moves an arm's tool to a target pose, keeping away from an obstacle
    # when something tracks one.
    class Reach < Syskit::Composition
      add Services::Pose, as: 'target'
      add OroGen.arm_control.TargetFilter, as: 'filter'
      add_optional Services::Pose, as: 'obstacle'
      add(ArmControl, as: 'control')
        .use('controller' => OroGen.arm_control.CartesianController)
        .with_conf('gentle')

      target_child.pose_samples_port.connect_to filter_child.raw_port
      filter_child.smoothed_port.connect_to control_child.target_port
      obstacle_child.pose_samples_port.connect_to control_child.obstacle_port

      export control_child.status_port
    end
  end
end
