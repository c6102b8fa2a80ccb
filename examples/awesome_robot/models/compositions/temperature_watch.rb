require 'models/devices/temperature/can_sensor'
using_task_library 'navigation'

module AwesomeRobot
  module Compositions
    # Watches two temperature probes: both feed one monitor.
    class TemperatureWatch < Syskit::Composition
      add Devices::Temperature::CANSensor, as: 'engine'
      add Devices::Temperature::CANSensor, as: 'water'
      add OroGen.navigation.TemperatureMonitor, as: 'monitor'

      engine_child.temperature_port.connect_to monitor_child.temperatures_port
      water_child.temperature_port.connect_to monitor_child.temperatures_port

      # The alarm's threshold for hot days.
      conf 'summer', monitor_child => %w[default summer]
    end
  end
end
