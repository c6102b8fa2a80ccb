require 'syskit/test'

module AwesomeRobot
  module Profiles
    module Live
      describe Base do
        it { is_self_contained }
        it { can_instanciate }
        it { can_deploy }
        it { can_configure }
        it { can_configure_together }
        it { can_configure(Base.gps_dev, Base.forward_camera_dev) }
        it { can_deploy(Base.drive_def, Base.watch_temperatures_def) }
      end
    end
  end
end
