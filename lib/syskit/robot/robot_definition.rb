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
    end
  end
end
