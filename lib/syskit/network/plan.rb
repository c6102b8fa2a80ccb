# frozen_string_literal: true

module Syskit
  module Network
    # The connection plan of a profile: which tasks run, deployed where,
    # configured how, connected how, in which order. A frozen value, built
    # from a generated network; renderers only read it.
    class Plan
      # A task of the plan, named after its deployed task; +devices+ are the
      # devices it drives, each followed by its slaves (+stereo.left+);
      # +unmanaged+: its deployment is started outside of Syskit;
      # +operations+: the operations its configure called, in call order.
      Task = Struct.new(:name, :model, :deployment, :devices, :conf, :properties, :ports, :depends_on, :unmanaged,
                        :operations)
      # A call of an operation of a task's component, and its arguments as
      # plain data; +argument_names+ are those of the operation's declaration
      # (empty when the spec does not declare it).
      Operation = Struct.new(:name, :arguments, :argument_names)
      # A port of a task; dynamic ports are created at configure time.
      # +declared_type+: the typedef name the port was declared with, when
      # it is not +type+ (nil otherwise).
      Port = Struct.new(:name, :direction, :type, :dynamic, :declared_type)
      # One end of a connection.
      Endpoint = Struct.new(:task, :port)
      # A connection and its policy ({'type' => 'buffer', 'size' => n} or {'type' => 'data'}).
      Connection = Struct.new(:from, :to, :type, :policy)
      # 'configure' or 'start' a task.
      Step = Struct.new(:step, :task)
      # A device of the network: its driver task, its bus and what it
      # declared (attributes such as can_id, period, burst). A slave device
      # is named +master.slave+, its +master+ is the master's name (nil for
      # the others) and its task is the master's. +com_bus+: the device is a
      # communication bus (other devices may be attached through it).
      Device = Struct.new(:name, :model, :task, :bus, :bus_to_client, :client_to_bus, :attributes,
                          :period, :burst, :sample_size, :declared_at, :master, :com_bus)
      # A CAN bus of the plan and the frames declared on its wire (by every
      # device of the robot attached to it or to a CAN bus attached to it),
      # in priority order; +bitrate+ and +utilization+ (a Rational) are nil
      # when no bitrate is declared.
      Bus = Struct.new(:name, :bitrate, :utilization, :frames)
      # A frame declared on a bus; times are Rational seconds.
      Frame = Struct.new(:id, :extended, :bytes, :period, :deadline, :jitter, :device, :declared_at)

      # Entries are built by position, the fast way; tests and tools name
      # the fields they need (the others are nil):
      # +Plan::Device.with(name: 'gps', bus: 'can0')+.
      module ByField
        def with(**fields)
          unknown = fields.keys - members
          unless unknown.empty?
            raise ArgumentError, "#{name} has no #{unknown.join(', ')}; its fields are #{members.join(', ')}"
          end

          new(*members.map { |m| fields[m] })
        end
      end
      [Task, Port, Device].each { |entry| entry.extend(ByField) }

      attr_reader :profile, :robot, :tasks, :devices, :connections, :order, :buses

      NO_ATTRIBUTES = {}.freeze
      NO_DEPENDENCIES = [].freeze
      NO_OPERATIONS = [].freeze

      def self.build(context)
        # The plan entries of a model's static ports are shared by its
        # tasks; a file's path relative to the app is computed once.
        static_ports = {}
        paths = {}
        new(
          profile: context.profile&.name, robot: context.robot_config&.name,
          tasks: context.tasks_by_name.map { |t| task_entry(t, static_ports) },
          devices: device_entries(context, paths),
          connections: context.connections.map { |c| connection_entry(c) }.sort_by! { |c| connection_key(c) },
          order: context.order.map { |s| Step.new(s.step, s.task.name).freeze },
          buses: bus_entries(context, paths)
        )
      end

      # The CAN buses of the plan that have a wire of their own (not
      # attached to another CAN bus), by name.
      def self.bus_entries(context, paths)
        context.tasks_by_name.filter_map do |task|
          bus = context.device_of(task)
          next unless bus.com_bus? && Robot::CanTraffic.can_bus?(bus) && bus.carrier.equal?(bus)

          frames = bus.frames_on_wire.sort_by.with_index { |f, i| [f.arbitration_key, f.device.to_s, i] }
          utilization = bus.bitrate && CAN::Timing.utilization(bus.bitrate, frames)
          Bus.new(bus.name, bus.bitrate, utilization, frames.map { |f| frame_entry(f, paths) }.freeze).freeze
        end
      end

      # The plan entry of a declared CAN::Timing::Frame.
      def self.frame_entry(frame, paths)
        Frame.new(frame.id, frame.extended, frame.bytes, frame.period, frame.deadline, frame.jitter,
                  frame.device, declared_at(frame.location, paths)).freeze
      end

      # Entries are frozen as they are built, so the plan is a frozen value
      # without walking it again.
      def self.task_entry(task, static_ports)
        children = task.children
        deployment = task.deployed_task.deployment
        Task.new(
          task.name, task.model.name, deployment.name,                        # name, model, deployment
          device_names(task), task.conf,                                      # devices, conf (frozen)
          freeze_plain(task.properties.to_plain),                             # properties
          task_ports(task, static_ports),                                     # ports
          children.empty? ? NO_DEPENDENCIES : children.map(&:name).sort!.freeze, # depends_on
          deployment.unmanaged?,                                              # unmanaged
          operation_entries(task)                                             # operations
        ).freeze
      end

      def self.operation_entries(task)
        calls = task.operation_calls
        return NO_OPERATIONS if calls.empty?

        declared = task.model.spec&.all_operations || {}
        calls.map do |c|
          names = declared[c.name]&.arguments&.map { |(name, _)| name.to_s }.freeze || NO_OPERATIONS
          Operation.new(c.name, freeze_plain(c.arguments.map { |a| plain_argument(a) }), names).freeze
        end.freeze
      end

      # An operation's argument as plain data (typed values through their type).
      def self.plain_argument(value)
        case value
        when Types::StructValue then value.class.type.to_plain(value)
        when Array then value.map { |v| plain_argument(v) }
        when Symbol then value.to_s
        else value
        end
      end

      # The task's devices, each followed by its slaves.
      def self.device_names(task)
        devices = task.devices
        return devices.map(&:name).freeze if devices.all? { |d| d.slaves.empty? }

        devices.flat_map { |d| [d.name, *d.each_slave.map(&:full_name)] }.freeze
      end

      # A device entry per task, and one per slave of its device, by name.
      def self.device_entries(context, paths)
        entries = []
        context.tasks.each do |task|
          device = context.device_of(task)
          entries << device_entry(device, task, paths)
          device.each_slave { |slave| entries << device_entry(slave, task, paths) }
        end
        entries.sort_by!(&:name)
      end

      # The model's static ports, then those the task's configure created.
      def self.task_ports(task, static_ports)
        ports = static_ports[task.model] ||= task.model.ports.each_value.map do |p|
          port_entry(p)
        end.sort_by!(&:name).freeze
        return ports if task.created_ports.empty?

        (ports + task.created_ports.each_value.map { |p| port_entry(p) }).sort_by!(&:name).freeze
      end

      def self.device_entry(device, task, paths)
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
      def self.declared_at(location, paths)
        return unless location

        "#{paths[location.path] ||= location.relative_path}:#{location.lineno}"
      end

      DIRECTIONS = { input: 'input', output: 'output' }.freeze

      def self.port_entry(port)
        Port.new(port.name, DIRECTIONS.fetch(port.direction), port.type.name, port.dynamic?,
                 port.declared_type).freeze
      end

      def self.connection_entry(conn)
        Connection.new(
          Endpoint.new(conn.from_task.name, conn.from_port.name).freeze, # from
          Endpoint.new(conn.to_task.name, conn.to_port.name).freeze,     # to
          conn.from_port.type.name, conn.policy                          # type, policy (frozen)
        ).freeze
      end

      # DSL attributes by name, sorted.
      def self.plain_attributes(attributes)
        plain = {}
        attributes.keys.sort!.each { |k| plain[k.name] = attributes[k] }
        freeze_plain(plain)
      end

      # Freezes plain data (hashes, arrays, strings) all the way down.
      def self.freeze_plain(value)
        if value.is_a?(Hash)
          value.each_value { |v| freeze_plain(v) }
        elsif value.is_a?(Array)
          value.each { |v| freeze_plain(v) }
        end
        value.freeze
      end

      # One string per connection, compared as the four names in turn ("\0"
      # sorts before any character of a name).
      def self.connection_key(conn)
        "#{conn.from.task}\0#{conn.from.port}\0#{conn.to.task}\0#{conn.to.port}"
      end

      def initialize(profile:, robot:, tasks:, devices:, connections:, order:, buses: [])
        @profile = profile.freeze
        @robot = robot.freeze
        @tasks = tasks.freeze
        @devices = devices.freeze
        @connections = connections.freeze
        @order = order.freeze
        @buses = buses.freeze
        freeze
      end

      # The bus entry named +name+ (nil when the plan has none).
      def find_bus(name)
        buses.find { |b| b.name == name }
      end

      def find_task(name)
        tasks.find { |t| t.name == name }
      end

      def find_device(name)
        devices.find { |d| d.name == name }
      end

      # The devices attached to bus +name+, by name.
      def devices_on(bus_name)
        devices.select { |d| d.bus == bus_name }
      end

      # Connections out of +task+ (and +port+ if given).
      def connections_from(task, port = nil)
        connections.select { |c| c.from.task == task && (port.nil? || c.from.port == port) }
      end

      # Connections into +task+ (and +port+ if given).
      def connections_to(task, port = nil)
        connections.select { |c| c.to.task == task && (port.nil? || c.to.port == port) }
      end

      # The parts of the plan that are lists of entries, in document order
      # (after 'profile' and 'robot').
      LISTS = %w[tasks devices connections order buses].freeze

      # The plan as plain data, the JSON document's content.
      def to_h
        port_hashes = {}.compare_by_identity # port entries are shared by tasks of a model
        LISTS.each_with_object({ 'profile' => profile, 'robot' => robot }) do |list, plain|
          plain[list] = plain_entries(list, public_send(list), port_hashes)
        end
      end

      # +entries+ of list +list+ (one of LISTS) as plain data: hashes with
      # string keys, as in #to_h. +port_hashes+ keeps one hash per port entry.
      def plain_entries(list, entries, port_hashes = {}.compare_by_identity)
        return entries.map { |t| task_hash(t, port_hashes) } if list == 'tasks'

        hash = ENTRY_HASHES.fetch(list) { raise ArgumentError, "#{list} is not one of #{LISTS.join(', ')}" }
        entries.map { |entry| send(hash, entry) }
      end

      # The method making the plain data of an entry, by list (but tasks).
      ENTRY_HASHES = { 'devices' => :device_hash, 'connections' => :connection_hash, 'order' => :step_hash,
                       'buses' => :bus_hash }.freeze

      private

      def task_hash(task, port_hashes)
        {
          'name' => task.name, 'model' => task.model, 'deployment' => task.deployment,
          'devices' => task.devices, 'conf' => task.conf, 'properties' => task.properties,
          'ports' => task.ports.map { |p| port_hashes[p] ||= port_hash(p) },
          'depends_on' => task.depends_on, 'unmanaged' => task.unmanaged,
          'operations' => task.operations.map { |op| { 'name' => op.name, 'arguments' => op.arguments } }
        }
      end

      def port_hash(port)
        hash = { 'name' => port.name, 'direction' => port.direction, 'type' => port.type, 'dynamic' => port.dynamic }
        port.declared_type ? hash.merge('declared_type' => port.declared_type) : hash
      end

      def device_hash(device)
        {
          'name' => device.name, 'model' => device.model, 'task' => device.task, 'bus' => device.bus,
          'bus_to_client' => device.bus_to_client, 'client_to_bus' => device.client_to_bus,
          'attributes' => device.attributes, 'period' => device.period, 'burst' => device.burst,
          'sample_size' => device.sample_size, 'declared_at' => device.declared_at, 'master' => device.master,
          'com_bus' => device.com_bus
        }
      end

      def step_hash(step)
        { 'step' => step.step, 'task' => step.task }
      end

      # Times in seconds, utilisation as a fraction, as `syskit bus timing`.
      def bus_hash(bus)
        {
          'name' => bus.name, 'bitrate' => bus.bitrate, 'utilization' => bus.utilization&.to_f,
          'frames' => bus.frames.map do |f|
            { 'id' => f.id, 'extended' => f.extended, 'bytes' => f.bytes, 'device' => f.device,
              'period' => f.period.to_f, 'deadline' => f.deadline.to_f, 'jitter' => f.jitter.to_f,
              'declared_at' => f.declared_at }
          end
        }
      end

      def connection_hash(conn)
        {
          'from' => { 'task' => conn.from.task, 'port' => conn.from.port },
          'to' => { 'task' => conn.to.task, 'port' => conn.to.port },
          'type' => conn.type, 'policy' => conn.policy
        }
      end
    end
  end
end
