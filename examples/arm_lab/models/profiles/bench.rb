require 'models/profiles/lab'

module ArmLab
  module Profiles
    # The cell without people: the target comes from a list of waypoints.
    profile 'Bench' do
      use_profile Lab, 'target' => OroGen.arm_control.WaypointPlayer
    end
  end
end
