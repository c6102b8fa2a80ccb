require 'models/devices/arm/six_axis'
require 'models/services/pose'

Syskit.extend_model OroGen.arm_control.ArmDriver do
  driver_for ArmLab::Devices::Arm::SixAxis, as: 'arm'
end

# Both controllers take a speed scale from the compositions that use them
# (see Compositions::ArmControl): it scales the max_speed of their
# configuration.
Syskit.extend_model OroGen.arm_control.JointPositionController do
  provides ArmLab::Services::JointsController, as: 'controller', 'status_in' => 'joints', 'command_out' => 'command'

  argument :speed_scale, default: 1.0

  def configure
    super
    properties.max_speed *= speed_scale
  end
end

Syskit.extend_model OroGen.arm_control.CartesianController do
  provides ArmLab::Services::JointsController, as: 'controller', 'status_in' => 'joints', 'command_out' => 'command'

  argument :speed_scale, default: 1.0

  def configure
    super
    properties.max_speed *= speed_scale
  end
end

Syskit.extend_model OroGen.arm_control.WaypointPlayer do
  provides ArmLab::Services::Pose, as: 'target', 'pose_samples' => 'waypoint'
end
