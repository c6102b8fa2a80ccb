module AwesomeRobot
  module Services
    # A position estimate.
    data_service_type 'Position' do
      output_port 'position_samples', '/base/samples/RigidBodyState'
    end
  end
end
