using_task_library 'gps_ublox'
using_task_library 'camera_gige'
using_task_library 'canbus'
using_task_library 'simple_can'
using_task_library 'can_temperature_sensor'
using_task_library 'can_open'
using_task_library 'roboteq'
using_task_library 'nmea2000'
require 'models/compositions/drive'
require 'models/compositions/temperature_watch'

module AwesomeRobot
  module Profiles
    module Live
      # The robot as it is in the field.
      profile 'Base' do
        robot do
          device(Devices::GPS::Ublox::F9, as: 'gps')
            .period(0.1)

          device(Devices::Camera::GigE, as: 'forward_camera')
            .prefer_deployed_tasks(/forward/)
            .with_conf('default', 'forward')
          device(Devices::Camera::GigE, as: 'aft_camera')
            .prefer_deployed_tasks(/aft/)
            .with_conf('default', 'aft')

          # Two CAN drivers are loaded, so each bus names its own. can0
          # runs at NMEA 2000's 250 kbit/s; .frame declares the traffic each
          # device puts on it, for `syskit bus timing` and `syskit check`.
          com_bus(CommonModels::Devices::Bus::CAN, as: 'can0', using: OroGen.canbus.Task)
            .bitrate(250_000)
          through 'can0' do
            device(OroGen.can_temperature_sensor.Task, as: 'temperature_sensor')
              .can_id(0x1234, 0xffff) # CAN ID filter
              .prefer_deployed_tasks('temperature_sensor')
              .period(0.1)
              .frame(0x1234, bytes: 2, period: 0.1, jitter: 0.0005, extended: true)
            device(Devices::Temperature::CANSensor, as: 'water_temperature', client_to_bus: false)
              .can_id(0x300, 0x7f0)
              .prefer_deployed_tasks('water_temperature')
              .frame(0x301, bytes: 2, period: 0.2, jitter: 0.0005) # three probes, every 200 ms
              .frame(0x302, bytes: 2, period: 0.2, jitter: 0.0005)
              .frame(0x303, bytes: 2, period: 0.2, jitter: 0.0005)
            # CANopen SYNC, every 10 ms: due 2 ms after its release, sent
            # within 0.1 ms of it.
            device(OroGen.can_open.SyncTask, as: 'sync', bus_to_client: false)
              .can_id(0x80, 0x7ff)
              .period(0.01)
              .burst(2)
              .frame(0x80, bytes: 0, period: 0.01, deadline: 0.002, jitter: 0.0001)
            # NMEA2000 frames (extended ids, PGN in bits 8..25) go to their
            # own demultiplexer, a bus attached to this bus.
            com_bus(Devices::N2k::Bus, as: 'n2k', client_to_bus: false)
              .can_id(0x1F21100, 0x3FFFF00)
          end
          through 'n2k' do
            # Its frames travel on can0's wire.
            device(Devices::N2k::FluidLevel, as: 'fuel_level', client_to_bus: false)
              .period(1)
              .frame(0x19F21123, bytes: 8, period: 1)
          end

          # A bus driver that does not demultiplex: the motor drivers filter
          # the frames themselves, with their own can_id/can_mask. Each
          # controller sends its feedback (TPDO1) every millisecond and gets
          # a command (RPDO1) from the host as often, up to 0.2 ms late; a
          # heartbeat every 100 ms.
          com_bus(CommonModels::Devices::Bus::CAN, as: 'can1', using: OroGen.simple_can.Task)
            .bitrate(1_000_000)
          through 'can1' do
            device(Devices::Roboteq::CANOpen, as: 'left_motor')
              .can_id(0x181, 0x7ff)
              .prefer_deployed_tasks(/left/)
              .frame(0x181, bytes: 8, period: 0.001)
              .frame(0x201, bytes: 8, period: 0.001, jitter: 0.0002)
              .frame(0x701, bytes: 1, period: 0.1)
            device(Devices::Roboteq::CANOpen, as: 'right_motor')
              .can_id(0x182, 0x7ff)
              .prefer_deployed_tasks(/right/)
              .frame(0x182, bytes: 8, period: 0.001)
              .frame(0x202, bytes: 8, period: 0.001, jitter: 0.0002)
              .frame(0x702, bytes: 1, period: 0.1)
          end
        end

        # What the robot runs: compositions of its devices' drivers and
        # other components. Each gives the profile an action (drive_def).

        # Follows the path with the GPS pose, at half speed.
        define 'drive', Compositions::Drive
          .use('position' => gps_dev, 'left' => left_motor_dev, 'right' => right_motor_dev)
          .with_arguments(max_speed: 0.5)
        # Alarms on the engine and water temperatures.
        define 'watch_temperatures', Compositions::TemperatureWatch
          .use('engine' => temperature_sensor_dev, 'water' => water_temperature_dev)
          .with_conf('summer')
      end
    end
  end
end
