require 'models/devices/gps/ublox/f9'

Syskit.extend_model OroGen.gps_ublox.F9Task do
  driver_for AwesomeRobot::Devices::GPS::Ublox::F9, as: 'f9'
end
