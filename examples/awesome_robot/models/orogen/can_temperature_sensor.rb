require 'models/devices/temperature/can_sensor'

Syskit.extend_model OroGen.can_temperature_sensor.Task do
  driver_for AwesomeRobot::Devices::Temperature::CANSensor, as: 'sensor'
end
