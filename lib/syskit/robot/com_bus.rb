# frozen_string_literal: true

require 'syskit/robot/master_device_instance'

module Syskit
  module Robot
    # A communication bus on a robot (+com_bus CAN, as: 'can0'+). It is a
    # device too: its driver is the bus driver task.
    class ComBus < MasterDeviceInstance
      include CanTraffic::BusStatements

      def initialize(*args)
        super
        @attached_devices = []
      end

      def com_bus?
        true
      end

      def message_type
        model.message_type
      end

      # Devices declared on this bus, in declaration order.
      def each_attached_device(&block)
        return enum_for(__method__) unless block

        @attached_devices.each(&block)
      end

      def attached_devices
        @attached_devices.dup
      end

      def add_attached_device(device)
        @attached_devices << device
      end

      # Syskit's forms on the bus object: +can0.through do device(...) end+,
      # as +through 'can0' do ... end+ in the robot block.
      def through(&)
        DSL.new(robot).through(self, &)
      end

      # +can0.device(Model, as: 'name', client_to_bus: false)+: a device
      # declared attached to this bus.
      def device(model, **options)
        DSL.new(robot).device_on(self, model, **options)
      end

      def to_s
        "bus '#{name}'"
      end
    end
  end
end
