# frozen_string_literal: true

module Syskit
  module Network
    class Plan
      # How a Plan is made of a generated network: its entries, each frozen
      # as it is built (so the plan is a frozen value without walking it
      # again), sorted by name where order is not meaningful.
      module Builder
        module_function

        NO_ATTRIBUTES = {}.freeze
        NO_DEPENDENCIES = [].freeze
        NO_OPERATIONS = [].freeze

        def build(context)
          # The plan entries of a model's static ports are shared by its
          # tasks; a file's path relative to the app is computed once.
          static_ports = {}
          paths = {}
          depends = {}.compare_by_identity
          Plan.new(
            profile: context.profile&.name, robot: context.robot_config&.name,
            tasks: context.tasks_by_name.map { |t| task_entry(t, static_ports, depends, context.robot_config) },
            devices: device_entries(context, paths),
            connections: connection_entries(context),
            order: context.order,
            buses: bus_entries(context, paths),
            compositions: context.compositions.map { |c| composition_entry(c) }.sort_by!(&:name)
          )
        end

        # A composition, its exports followed down to the tasks that have
        # the ports; the action it was made for when it is a root.
        def composition_entry(composition)
          requirement = composition.requirements
          Composition.new(
            composition.name, composition.model.short_name,
            (requirement.to_s if requirement.name && !composition.parent),
            composition_arguments(composition),
            composition.conf, composition.children_by_role.transform_values(&:name).freeze,
            export_entries(composition), composition.parent&.name
          ).freeze
        end

        # The composition's arguments, defaults included, but its sections
        # (which the entry has on their own).
        def composition_arguments(composition)
          arguments = composition.arguments.except(:conf)
          freeze_plain(arguments.sort.to_h { |k, v| [k.to_s, plain_argument(v)] })
        end

        def export_entries(composition)
          composition.model.exports.keys.sort.each_with_object({}) do |name, all|
            task, port = composition.resolve_export(name)
            all[name] = Endpoint.new(task.name, port).freeze if task
          end.freeze
        end

        # The CAN buses of the plan that have a wire of their own (not
        # attached to another CAN bus), by name.
        def bus_entries(context, paths)
          context.tasks_by_name.filter_map do |task|
            bus = context.device_of(task)
            next unless bus&.com_bus? && Robot::CanTraffic.can_bus?(bus) && bus.carrier.equal?(bus)

            frames = bus.frames_on_wire.sort_by.with_index { |f, i| [f.arbitration_key, f.device.to_s, i] }
            utilization = bus.bitrate && CAN::Timing.utilization(bus.bitrate, frames)
            Bus.new(bus.name, bus.bitrate, utilization, frames.map { |f| frame_entry(f, paths) }.freeze).freeze
          end
        end

        # The plan entry of a declared CAN::Timing::Frame.
        def frame_entry(frame, paths)
          Frame.new(frame.id, frame.extended, frame.bytes, frame.period, frame.deadline, frame.jitter,
                    frame.device, declared_at(frame.location, paths)).freeze
        end

        # Entries are frozen as they are built, so the plan is a frozen value
        # without walking it again.
        def task_entry(task, static_ports, depends, robot_config)
          children = task.children
          deployment = task.deployed_task.deployment
          Task.new(
            task.name, task.model.name, deployment.name,                        # name, model, deployment
            device_names(task), task.conf,                                      # devices, conf (frozen)
            freeze_plain(task.properties.to_plain),                             # properties
            task_ports(task, static_ports),                                     # ports
            depends_on(children, depends),                                      # depends_on
            deployment.unmanaged?,                                              # unmanaged
            operation_entries(task),                                            # operations
            process_server_entry(robot_config, deployment)                      # process_server
          ).freeze
        end

        # The names of a task's children, sorted; the tasks of the devices of
        # a bus share their list of children (see TaskContext#add_child), so
        # they share its entry too (+depends+, by list).
        def depends_on(children, depends)
          return NO_DEPENDENCIES if children.empty?

          depends[children] ||= children.map(&:name).sort!.freeze
        end

        # Where +deployment+ runs, when the robot configuration says (on:).
        def process_server_entry(config, deployment)
          name = config&.process_server_of(deployment.name)
          server = name && config.process_server_named(name)
          { 'name' => server.name, 'host' => server.host }.freeze if server
        end

        def operation_entries(task)
          calls = task.operation_calls
          return NO_OPERATIONS if calls.empty?

          declared = task.model.spec&.all_operations || {}
          calls.map do |c|
            names = declared[c.name]&.arguments&.map { |(name, _)| name.to_s }.freeze || NO_OPERATIONS
            Operation.new(c.name, freeze_plain(c.arguments.map { |a| plain_argument(a) }), names).freeze
          end.freeze
        end

        # An operation's argument as plain data (typed values through their type).
        def plain_argument(value)
          case value
          when Compat::Roby::DefaultArgument then plain_argument(value.value)
          when Types::StructValue then value.class.type.to_plain(value)
          when Array then value.map { |v| plain_argument(v) }
          when Hash then value.to_h { |k, v| [k.to_s, plain_argument(v)] }
          when Symbol, Robot::MasterDeviceInstance, Module then value.to_s
          else value
          end
        end

        # The task's devices, each followed by its slaves.
        def device_names(task)
          devices = task.devices
          return devices.map(&:name).freeze if devices.all? { |d| d.slaves.empty? }

          devices.flat_map { |d| [d.name, *d.each_slave.map(&:full_name)] }.freeze
        end

        # A device entry per task, and one per slave of its device, by name.
        def device_entries(context, paths)
          entries = []
          context.tasks.each do |task|
            device = context.device_of(task)
            next unless device

            entries << device_entry(device, task, paths)
            device.each_slave { |slave| entries << device_entry(slave, task, paths) }
          end
          entries.sort_by!(&:name)
        end

        # The model's static ports, then those the task's configure created.
        # The state port every task context has (oroGen's extended state
        # support) is left out unless it is connected, as Syskit's network
        # views show only connected ports.
        def task_ports(task, static_ports)
          ports = static_ports[task.model] ||= task.model.ports.each_value.filter_map do |p|
            port_entry(p) unless Orogen::TaskSpec.state_port?(p)
          end.sort_by!(&:name).freeze
          created = task.created_ports
          state = task.model.ports[Orogen::TaskSpec::STATE_PORT]
          state = nil unless state && state_port_connected?(task, state)
          return ports if created.empty? && !state

          extra = created.values.map! { |p| port_entry(p) }
          extra << port_entry(state) if state
          (ports + extra).sort_by!(&:name).freeze
        end

        def state_port_connected?(task, state)
          Orogen::TaskSpec.state_port?(state) &&
            task.connections.any? { |c| c.from_task.equal?(task) && c.from_port.name == state.name }
        end

        def device_entry(device, task, paths)
          attributes = device.dsl_attributes
          attached = device.attached?
          Device.new(
            device.full_name, device.model.name, task.name, device.bus&.name,   # name, model, task, bus
            attached ? device.bus_to_client? : nil,                             # bus_to_client
            attached ? device.client_to_bus? : nil,                             # client_to_bus
            attributes.empty? ? NO_ATTRIBUTES : plain_attributes(attributes),   # attributes
            device.period, device.burst, device.sample_size,                    # period, burst, sample_size
            declared_at(device.declared_at, paths),                             # declared_at
            device.master_device&.name,                                         # master
            device.com_bus?                                                     # com_bus
          ).freeze
        end

        # "path:line", the path relative to the app (computed once per file).
        def declared_at(location, paths)
          return unless location

          # format writes the line number into the string (interpolation
          # would make a string of it first).
          format('%s:%d', paths[location.path] ||= location.relative_path, location.lineno) # rubocop:disable Style/FormatStringToken
        end

        DIRECTIONS = { input: 'input', output: 'output' }.freeze

        def port_entry(port)
          Port.new(port.name, DIRECTIONS.fetch(port.direction), port.type.name, port.dynamic?,
                   port.declared_type).freeze
        end

        # The connections, sorted by their four names in turn (source task,
        # source port, sink task, sink port). They are taken from their
        # source tasks, which come by name: only the connections of a task
        # that is the source of several (a bus driver) are sorted, without
        # a sort key made for every connection.
        def connection_entries(context)
          endpoints = [{}.compare_by_identity, {}.compare_by_identity] # by task: last source, last sink
          entries = []
          context.tasks_by_name.each do |task|
            first = entries.size
            each_connection_from(task) { |c| entries << connection_entry(c, endpoints) }
            next if entries.size - first < 2

            entries.concat(entries.pop(entries.size - first).sort! { |a, b| compare_from_one_task(a, b) })
          end
          entries
        end

        # The connections of which +task+ is the source. A connection from
        # a task to itself is twice in its list: it is taken once. (Array's
        # each_index: Enumerable's each_with_index makes two objects a call.)
        def each_connection_from(task)
          connections = task.connections
          connections.each_index do |i|
            c = connections[i]
            next unless c.from_task.equal?(task)
            next if c.to_task.equal?(task) && connections.index { |other| other.equal?(c) } != i

            yield c
          end
        end

        # Two connections from the same task, by source port, sink task and
        # sink port.
        def compare_from_one_task(one, other)
          (one.from.port <=> other.from.port).nonzero? || (one.to.task <=> other.to.task).nonzero? ||
            (one.to.port <=> other.to.port)
        end

        def connection_entry(conn, endpoints)
          Connection.new(
            endpoint(conn.from_task, conn.from_port, endpoints[0]), # from
            endpoint(conn.to_task, conn.to_port, endpoints[1]),     # to
            conn.from_port.type.name, conn.policy                   # type, policy (frozen)
          ).freeze
        end

        # The endpoint of +task+'s +port+. A bus driver's port shared by
        # its devices is in a connection per device, one device after the
        # other: the last endpoint of each task on each side of a connection
        # is kept (+endpoints+) and used again.
        def endpoint(task, port, endpoints)
          last = endpoints[task]
          return last if last && last.port == port.name

          endpoints[task] = Endpoint.new(task.name, port.name).freeze
        end

        # DSL attributes by name, sorted.
        def plain_attributes(attributes)
          plain = {}
          # Most devices have one (can_id): no sorted list of one is made.
          if attributes.size == 1
            attributes.each { |k, v| plain[k.name] = v }
          else
            attributes.keys.sort!.each { |k| plain[k.name] = attributes[k] }
          end
          freeze_plain(plain)
        end

        # Freezes plain data (hashes, arrays, strings) all the way down.
        def freeze_plain(value)
          if value.is_a?(Hash)
            value.each_value { |v| freeze_plain(v) }
          elsif value.is_a?(Array)
            value.each { |v| freeze_plain(v) }
          end
          value.freeze
        end
      end
    end
  end
end
