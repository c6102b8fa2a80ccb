# frozen_string_literal: true

module Syskit
  module Compat
    # rock_gazebo's profile statement +use_gazebo_model 'model://ur10'+,
    # as far as a plan needs it: the robot gets the device of the model
    # (+ur10_dev+, a CommonModels::Devices::Gazebo::RootModel driven by
    # rock_gazebo::ModelTask), run by the simulator (an unmanaged deployed
    # task, gazebo_ur10). Its links, joints and sensors, which rock_gazebo
    # reads from the model's SDF file, are not modelled: one warning says
    # so. Without common_models' Gazebo models or the rock_gazebo task
    # library, the whole statement is not modelled.
    module Gazebo
      module_function

      # Declares the model's device on +profile+'s robot; nil when it
      # cannot (the statement is then not modelled).
      def use_model(profile, url, as:, location:)
        app = Syskit.app
        name = (as || url.to_s.sub(%r{\Amodel://}, '').split('/').first).to_s.gsub(/::+/, '_')
        model, driver = device_and_driver(app, location) if app && name.match?(/\A[a-z_]\w*\z/i)
        return unless model && driver

        app.not_modelled("the links, joints and sensors of #{url} (use_gazebo_model reads them from its SDF file)",
                         location)
        device = profile.robot.add_device(Robot::MasterDeviceInstance, model, name, using: driver, options: {},
                                                                                    location: location)
        device.deployed_as_unmanaged("gazebo_#{name}")
        define_sdf_model(profile.namespace)
        device
      end

      # +profile.sdf_model+, which configure methods read the model's SDF
      # from: not modelled (what is made of it is not modelled either).
      def define_sdf_model(namespace)
        namespace.define_singleton_method(:sdf_model) do
          Syskit.app&.not_modelled("the SDF model of #{self}", Location.of_caller)
          Compat::Ignored.instance
        end
      end

      def device_and_driver(app, location)
        return unless app.orogen.available_library_names.include?('rock_gazebo')

        require 'common_models/models/devices/gazebo/root_model'
        app.using_task_library('rock_gazebo', location: location)
        [CommonModels::Devices::Gazebo::RootModel, OroGen.rock_gazebo.ModelTask]
      rescue LoadError, NameError
        nil
      end
    end
  end
end
