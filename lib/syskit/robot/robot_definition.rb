# frozen_string_literal: true

require 'syskit/robot/definition'
require 'syskit/robot/dsl'

module Syskit
  module Robot
    # A robot made alone, as Syskit's tests make one
    # (+Syskit::Robot::RobotDefinition.new.device(Devices::Camera, as: 'x', using: model)+):
    # the statements of a robot block are its methods. As in Syskit, each
    # device gets its driver as it is declared (+using:+, else the one
    # driver of its model), among the loaded task models and those made in
    # Ruby so far (+Syskit::TaskContext.new_submodel { driver_for ... }+).
    class RobotDefinition < Definition
      # +profile+: the profile made in Ruby whose robot it is
      # (+Actions::Profile.new.robot.device(...)+ gives the profile its
      # +x_dev+ action), none for a robot made alone.
      def initialize(profile = nil)
        super
        @dsl = DSL.new(self)
      end

      def device(...)
        resolve_now(@dsl.device(...))
      end

      def com_bus(...)
        resolve_now(@dsl.com_bus(...))
      end

      def through(...)
        @dsl.through(...)
      end

      # Each device is also +robot.name_dev+, as Syskit's robots give them.
      def add_device(...)
        device = super
        reader = "#{device.name}_dev"
        define_singleton_method(reader) { device } unless respond_to?(reader)
        device
      end

      private

      # Without an app there is nothing to find drivers among yet.
      def resolve_now(device)
        app = Syskit.app
        DriverIndex.new(app.orogen, app, task_models: ruby_task_models).resolve(device) if app
        device.check_combus_attachment
        device
      rescue Syskit::Error
        @devices.delete(device.name)
        raise
      end

      def ruby_task_models
        Models.defined_models.select { |m| m.is_a?(Class) && m < RubyTaskContext }
      end
    end
  end
end
