require 'models/compositions/reach'

module ArmLab
  module Compositions
    describe Reach do
      it 'feeds the Cartesian controller with the target, smoothed' do
        cmp = syskit_stub_and_deploy(Reach.use('target' => OroGen.arm_control.WaypointPlayer))
        controller = cmp.control_child.controller_child
        assert_kind_of OroGen.arm_control.CartesianController, controller
        assert cmp.target_child.waypoint_port.connected_to?(cmp.filter_child.raw_port)
        assert cmp.filter_child.smoothed_port.connected_to?(controller.target_port)
      end

      it 'keeps away from the obstacle when something tracks one' do
        cmp = syskit_stub_and_deploy(Reach.use('target' => OroGen.arm_control.WaypointPlayer,
                                               'obstacle' => OroGen.mocap.BodyTask))
        assert cmp.obstacle_child.pose_samples_port.connected_to?(cmp.control_child.controller_child.obstacle_port)
      end
    end
  end
end
