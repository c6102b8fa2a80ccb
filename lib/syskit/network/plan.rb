# frozen_string_literal: true

module Syskit
  module Network
    # The connection plan of a profile: which tasks run, deployed where,
    # configured how, connected how, in which order. A frozen value, built
    # from a generated network; renderers only read it.
    class Plan
      # A task of the plan, named after its deployed task; +devices+ are the
      # devices it drives, each followed by its slaves (+stereo.left+);
      # +unmanaged+: its deployment is started outside of Syskit.
      Task = Struct.new(:name, :model, :deployment, :devices, :conf, :properties, :ports, :depends_on, :unmanaged)
      # A port of a task; dynamic ports are created at configure time.
      Port = Struct.new(:name, :direction, :type, :dynamic)
      # One end of a connection.
      Endpoint = Struct.new(:task, :port)
      # A connection and its policy ({'type' => 'buffer', 'size' => n} or {'type' => 'data'}).
      Connection = Struct.new(:from, :to, :type, :policy)
      # 'configure' or 'start' a task.
      Step = Struct.new(:step, :task)
      # A device of the network: its driver task, its bus and what it
      # declared (attributes such as can_id, period, burst). A slave device
      # is named +master.slave+, its +master+ is the master's name (nil for
      # the others) and its task is the master's.
      Device = Struct.new(:name, :model, :task, :bus, :bus_to_client, :client_to_bus, :attributes,
                          :period, :burst, :sample_size, :declared_at, :master)

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

      attr_reader :profile, :robot, :tasks, :devices, :connections, :order

      NO_ATTRIBUTES = {}.freeze
      NO_DEPENDENCIES = [].freeze

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
          order: context.order.map { |s| Step.new(s.step, s.task.name).freeze }
        )
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
          deployment.unmanaged? # unmanaged
        ).freeze
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
          device.master_device&.name                                          # master
        ).freeze
      end

      # "path:line", the path relative to the app (computed once per file).
      def self.declared_at(location, paths)
        return unless location

        "#{paths[location.path] ||= location.relative_path}:#{location.lineno}"
      end

      DIRECTIONS = { input: 'input', output: 'output' }.freeze

      def self.port_entry(port)
        Port.new(port.name, DIRECTIONS.fetch(port.direction), port.type.name, port.dynamic?).freeze
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

      def initialize(profile:, robot:, tasks:, devices:, connections:, order:)
        @profile = profile.freeze
        @robot = robot.freeze
        @tasks = tasks.freeze
        @devices = devices.freeze
        @connections = connections.freeze
        @order = order.freeze
        freeze
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
      LISTS = %w[tasks devices connections order].freeze

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
        case list
        when 'tasks' then entries.map { |t| task_hash(t, port_hashes) }
        when 'devices' then entries.map { |d| device_hash(d) }
        when 'connections' then entries.map { |c| connection_hash(c) }
        when 'order' then entries.map { |s| { 'step' => s.step, 'task' => s.task } }
        else raise ArgumentError, "#{list} is not one of #{LISTS.join(', ')}"
        end
      end

      private

      def task_hash(task, port_hashes)
        {
          'name' => task.name, 'model' => task.model, 'deployment' => task.deployment,
          'devices' => task.devices, 'conf' => task.conf, 'properties' => task.properties,
          'ports' => task.ports.map { |p| port_hashes[p] ||= port_hash(p) },
          'depends_on' => task.depends_on, 'unmanaged' => task.unmanaged
        }
      end

      def port_hash(port)
        { 'name' => port.name, 'direction' => port.direction, 'type' => port.type, 'dynamic' => port.dynamic }
      end

      def device_hash(device)
        {
          'name' => device.name, 'model' => device.model, 'task' => device.task, 'bus' => device.bus,
          'bus_to_client' => device.bus_to_client, 'client_to_bus' => device.client_to_bus,
          'attributes' => device.attributes, 'period' => device.period, 'burst' => device.burst,
          'sample_size' => device.sample_size, 'declared_at' => device.declared_at, 'master' => device.master
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
