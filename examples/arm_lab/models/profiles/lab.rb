using_task_library 'arm_control'
using_task_library 'mocap'
require 'models/compositions/arm_control'
require 'models/compositions/reach'

module ArmLab
  module Profiles
    # The lab's cell: two arms, and a wand people point with, tracked by
    # the motion-capture system.
    profile 'Lab' do
      robot do
        device(Devices::Arm::SixAxis, as: 'left_arm')
          .with_conf('default', 'left')
          .prefer_deployed_tasks('left_arm')
        device(Devices::Arm::SixAxis, as: 'right_arm')
          .with_conf('default', 'right')
          .prefer_deployed_tasks('right_arm')
        device(Devices::Mocap::Body, as: 'wand')
      end

      # What the arms reach for: the profiles using this one choose it.
      tag 'target', Services::Pose

      # Joint position control, unless a definition says otherwise.
      use Services::JointsController => OroGen.arm_control.JointPositionController

      # Holds the right arm where it is told.
      define 'right_hold', Compositions::ArmControl.use('arm' => right_arm_dev)
      # The same, at a quarter of the speed and soft.
      define 'right_hold_gentle', right_hold_def.with_conf('gentle').with_arguments(speed_scale: 0.25)

      # The left arm's tool follows the wand.
      define 'follow_wand', Compositions::Reach.use('target' => wand_dev, 'control.arm' => left_arm_dev)
      # The left arm reaches for the target, keeping away from the wand.
      define 'reach_target', Compositions::Reach
        .use('target' => target_tag, 'obstacle' => wand_dev, 'control.arm' => left_arm_dev)
    end
  end
end
