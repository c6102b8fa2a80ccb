require 'models/devices/can_open_sync'

Syskit.extend_model OroGen.can_open.SyncTask do
  driver_for AwesomeRobot::Devices::CANOpenSync, as: 'sync'
end
