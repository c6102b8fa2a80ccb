# frozen_string_literal: true

require 'syskit/device_enumeration'

module Syskit
  module Robot
    # Finding a robot's devices, under Syskit's names (+robot.find_device('gps')+,
    # +has_device?('stereo.left')+, +each_master_device+). Part of Definition
    # (uses its +devices+ and the robots it uses).
    module RobotLookups
      # each_master_device (the devices and buses declared with device or
      # com_bus) and each_slave_device.
      include DeviceEnumeration

      # The device +name+; +master.slave+ names a slave device.
      def find_device(name)
        name = name.to_s
        found = @devices[name] || used_device(name)
        return found if found || !name.include?('.')

        master, slave = name.split('.', 2)
        find_device(master)&.find_slave(slave)
      end

      # The device +name+ of a used robot.
      def used_device(name)
        @used.each do |robot|
          found = robot.find_device(name)
          return found if found
        end
        nil
      end

      def device_names
        each_master_device.map(&:name)
      end

      # Enumerates the devices and buses themselves, in declaration order.
      def each_master_device
        return enum_for(__method__) unless block_given?

        devices.each_value { |device| yield(device) unless device.master_device }
      end

      # Whether +name+ is a device (or bus) of this robot; +master.slave+
      # names a slave device.
      def has_device?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        !find_device(name).nil?
      end

      # Enumerates the devices and buses, then the slave devices.
      def each_device(&block)
        return enum_for(__method__) unless block

        each_master_device(&block)
        each_slave_device(&block)
      end

      # Whether it has no device.
      def empty?
        each_master_device.none?
      end
    end
  end
end
