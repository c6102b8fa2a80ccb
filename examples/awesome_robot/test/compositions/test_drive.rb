require 'models/compositions/drive'

module AwesomeRobot
  module Compositions
    describe Drive do
      it 'feeds the path follower with the position it is given' do
        cmp = syskit_stub_and_deploy(Drive.use('position' => OroGen.gps_ublox.F9Task))
        assert cmp.position_child.pose_samples_port.connected_to?(cmp.follower_child.pose_port)
        assert cmp.follower_child.left_speed_port.connected_to?(cmp.left_child.speed_command_port)
      end

      it 'passes its speed down to the follower' do
        cmp = syskit_stub_deploy_and_configure(Drive.with_arguments(max_speed: 0.3))
        assert_equal 0.3, cmp.follower_child.properties.max_speed
      end
    end
  end
end
