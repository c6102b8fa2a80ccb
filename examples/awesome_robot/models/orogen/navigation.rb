Syskit.extend_model OroGen.navigation.PathFollower do
  # Set by the compositions that use the follower (see Compositions::Drive).
  argument :max_speed, default: 1.0

  def configure
    super
    properties.max_speed = max_speed
  end
end
