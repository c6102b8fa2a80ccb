# What runs in the cell: a deployed task per device, and the controllers.
Syskit.conf.use_deployment OroGen.arm_control.ArmDriver => 'left_arm'
Syskit.conf.use_deployment OroGen.arm_control.ArmDriver => 'right_arm'
Syskit.conf.use_deployment OroGen.mocap.BodyTask => 'wand'
Syskit.conf.use_deployment OroGen.arm_control.JointPositionController => 'joint_controller'
Syskit.conf.use_deployment OroGen.arm_control.CartesianController => 'cartesian_controller'
Syskit.conf.use_deployment OroGen.arm_control.TargetFilter => 'target_filter'
Syskit.conf.use_deployment OroGen.arm_control.WaypointPlayer => 'waypoints'
