# frozen_string_literal: true

require 'syskit/network/bus_ports'

module Syskit
  module Network
    # Step 2: for every attached device in the network, its bus driver task
    # (one per bus, itself attached to its own bus if any) becomes a
    # dependency of the device's task, and the ports that link them are
    # chosen (see BusPorts). A bus attached through itself never gets here:
    # the robot refuses it where it is declared.
    #
    # As in Syskit, a bus driver serves every device declared on its bus,
    # in the network or not: a bus planned alone gets the per-device ports
    # of all of them. A bus model declared with lazy_dispatch: true serves
    # only the devices whose tasks are in the network.
    class Buses
      # What a device's task knows of the bus it depends on (see
      # TaskContext#each_child).
      BUS_CHILD = { role: 'bus' }.freeze

      def initialize(context)
        @context = context
        @drivers = Drivers.new(context)
        @bus_ports = {}.compare_by_identity
      end

      def run
        queue = @context.tasks.dup
        bus_tasks = []
        until queue.empty?
          task = queue.shift
          device = @context.device_of(task)
          next unless device

          bus_tasks << task if device.com_bus?
          next unless device.attached?

          begin
            link(device, task, bus_task_for(device.bus, queue))
          rescue Syskit::Error => e
            @context.error(e)
          end
        end
        # Once the links are made (each link's ports are chosen where they
        # are used, the cheap order for the CPU caches), the devices not in
        # the network.
        bus_tasks.each { |task| serve_declared_devices(task) }
        check_port_names
      end

      private

      def link(device, task, bus_task)
        task.add_child(bus_task, BUS_CHILD)
        @context.bus_links << ports_of(bus_task).link(device, task)
      end

      # A BusPorts per bus driver task, not per device.
      def ports_of(bus_task)
        @bus_ports[bus_task] ||= BusPorts.new(bus_task, @context.expected_ports[bus_task])
      end

      def bus_task_for(bus, queue)
        existing = @context.task_for(bus)
        return existing if existing

        task = @drivers.instantiate(InstanceRequirements.new(device: bus, profile: @context.profile))
        queue << task
        task
      end

      # A bus task records the devices it serves, in declaration order: the
      # ones linked to it, and, unless it dispatches lazily, the others,
      # whose ports are chosen here.
      def serve_declared_devices(task)
        bus = @context.device_of(task)
        lazy = bus.model.lazy_dispatch?
        bus.each_attached_device do |device|
          if @context.task_for(device)
            task.attach_device(device)
          elsif !lazy
            serve_unplanned(device, task)
          end
        end
      end

      def serve_unplanned(device, task)
        ports_of(task).bus_side(device)
        task.attach_device(device)
      rescue Syskit::Error => e
        @context.error(e)
      end

      # Per-device ports of one bus driver must not collide with each other
      # (a device 'x' writes to 'wx', a device 'wx' reads from 'wx') nor with
      # the driver's own ports. Names are counted, and the ports of a name
      # gathered only when it clashes (no list per device otherwise).
      def check_port_names
        @context.expected_ports.each do |bus_task, ports|
          counts = ports.map(&:name).tally
          ports.each do |port|
            name = port.name
            if counts[name] > 1
              @context.error(port_clash(bus_task, name, ports.select { |p| p.name == name }))
              counts[name] = 0 # reported once
            elsif counts[name] == 1 && (static = bus_task.model.ports[name])
              @context.error(static_clash(bus_task, port, static))
            end
          end
        end
      end

      def port_clash(bus_task, name, ports)
        first, second = ports.map(&:device)
        NetworkError.new(
          "#{first} and #{second} both need a port named '#{name}' on #{bus_task.model.name} " \
          "(#{ports.map { |p| "#{p.direction} for #{p.device.name}" }.join(', ')}; " \
          "#{first} is declared at #{first.declared_at})",
          location: second.declared_at, hint: "rename one of them: per-device ports are '<name>' and 'w<name>'"
        )
      end

      def static_clash(bus_task, port, static)
        NetworkError.new(
          "the #{port.direction} port '#{port.name}' of #{port.device} on #{bus_task.model.name} " \
          "collides with its #{static}",
          location: port.device.declared_at, hint: 'rename the device'
        )
      end
    end
  end
end
