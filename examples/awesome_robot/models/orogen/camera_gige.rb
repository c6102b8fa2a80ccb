require 'models/devices/camera/gig_e'

Syskit.extend_model OroGen.camera_gige.Task do
  driver_for AwesomeRobot::Devices::Camera::GigE, as: 'camera'
end
