# frozen_string_literal: true

require 'syskit/robot/definition'
require 'syskit/robot/dsl'

module Syskit
  module Robot
    # A robot made alone, as Syskit's tests make one
    # (+Syskit::Robot::RobotDefinition.new.device(Devices::Camera, as: 'x', using: model)+):
    # the statements of a robot block are its methods.
    class RobotDefinition < Definition
      def initialize
        super(nil)
        @dsl = DSL.new(self)
      end

      %i[device com_bus through].each do |statement|
        define_method(statement) { |*args, **options, &block| @dsl.public_send(statement, *args, **options, &block) }
      end

      # Each device is also +robot.name_dev+, as Syskit's robots give them.
      def add_device(...)
        device = super
        reader = "#{device.name}_dev"
        define_singleton_method(reader) { device } unless respond_to?(reader)
        device
      end
    end
  end
end
