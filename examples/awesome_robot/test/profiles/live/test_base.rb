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
      end
    end
  end
end
