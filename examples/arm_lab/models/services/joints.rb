module ArmLab
  module Services
    # The measured state of a set of joints.
    data_service_type 'JointsStatus' do
      output_port 'status_out', '/base/samples/Joints'
    end

    # Something whose joints take commands.
    data_service_type 'JointsCommand' do
      input_port 'command_in', '/base/commands/Joints'
    end

    # A system of joints: commanded, and measured.
    data_service_type 'JointsControlledSystem' do
      provides JointsStatus
      provides JointsCommand
    end

    # A joint controller: reads the joints' state, writes their command.
    data_service_type 'JointsController' do
      input_port 'status_in', '/base/samples/Joints'
      output_port 'command_out', '/base/commands/Joints'
    end
  end
end
