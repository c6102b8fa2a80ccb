module ArmLab
  module Services
    # The pose of a rigid body.
    data_service_type 'Pose' do
      output_port 'pose_samples', '/base/samples/RigidBodyState'
    end
  end
end
