require 'models/profiles/lab'

module ArmLab
  module Profiles
    describe Lab do
      # The target is left to the profiles using this one.
      it { is_self_contained }
      it { can_deploy(Lab.right_hold_def, Lab.right_hold_gentle_def, Lab.follow_wand_def) }
      it { can_configure(Lab.left_arm_dev, Lab.right_arm_dev, Lab.wand_dev) }
      it { can_configure_together(Lab.right_hold_def, Lab.follow_wand_def) }
    end
  end
end
