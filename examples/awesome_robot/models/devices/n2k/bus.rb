module AwesomeRobot
  module Devices
    module N2k
      # NMEA2000: a CAN bus on which devices are told apart by PGN.
      com_bus_type 'Bus' do
        provides CommonModels::Devices::Bus::CAN
      end
    end
  end
end
