module AwesomeRobot
  module Devices
    module N2k
      # NMEA2000 device models know the PGN (message id) they send.
      class DeviceModel < Syskit::Models::DeviceModel
        # Sets the PGN with an argument, returns it without.
        def pgn(pgn = nil)
          return @pgn if pgn.nil?

          @pgn = Integer(pgn)
        end
      end

      # The root of NMEA2000 device models.
      Device = DeviceModel.new
      Device.provides Syskit::Device
    end
  end
end
