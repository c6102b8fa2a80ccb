require 'models/compositions/arm_control'

module ArmLab
  module Compositions
    describe ArmControl do
      it 'closes the loop between the controller and the arm' do
        cmp = syskit_stub_and_deploy(ArmControl.use('controller' => OroGen.arm_control.JointPositionController))
        assert cmp.arm_child.joints_status_port.connected_to?(cmp.controller_child.joints_port)
        assert cmp.controller_child.command_port.connected_to?(cmp.arm_child.joints_cmd_port)
      end

      it 'takes a setpoint with a joint position controller, a target with a Cartesian one' do
        joints = ArmControl.use('controller' => OroGen.arm_control.JointPositionController).narrow_model
        assert_equal %w[setpoint status], joints.each_port.map(&:name).sort
        cartesian = ArmControl.use('controller' => OroGen.arm_control.CartesianController).narrow_model
        assert_equal %w[obstacle status target], cartesian.each_port.map(&:name).sort
      end

      it 'scales the speed of its controller' do
        cmp = syskit_stub_deploy_and_configure(
          ArmControl.use('controller' => OroGen.arm_control.JointPositionController).with_arguments(speed_scale: 0.5)
        )
        assert_equal 0.25, cmp.controller_child.properties.max_speed
      end

      it 'configures its controller to be gentle' do
        cmp = syskit_stub_deploy_and_configure(
          ArmControl.use('controller' => OroGen.arm_control.CartesianController).with_conf('gentle')
        )
        assert_equal 0.6, cmp.controller_child.properties.clearance
      end
    end
  end
end
