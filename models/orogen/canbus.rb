# frozen_string_literal: true

# Syskit integration of the canbus component, configured as Rock's common
# models configure it: the bus driver takes every device's frames on its
# shared 'in' port (BusInSrv), and each device that reads from the bus is
# watched, which creates the output port named after it. A real
# common_models bundle's canbus extension replaces this one.
require 'common_models/models/devices/bus/can'

class OroGen::Canbus::Task
  driver_for CommonModels::Devices::Bus::CAN, as: 'can'
  provides CommonModels::Devices::Bus::CAN::BusInSrv, as: 'bus_in'

  def configure
    super

    each_declared_attached_device do |dev|
      next unless dev.bus_to_client?

      id, mask = dev.can_id
      unless id
        raise Syskit::ConfigurationError.new(
          "#{dev} is attached to #{can_dev} but has no CAN filter",
          location: dev.declared_at, hint: 'declare the frames it receives with .can_id(id, mask)'
        )
      end

      orocos_task.watch(dev.name, id, mask)
    end
  end

  # What the component does when watch is called: a port for the device.
  stub do
    def watch(name, _id, _mask)
      create_output_port name, '/canbus/Message'
      true
    end

    def unwatch(_name)
      true
    end
  end
end
