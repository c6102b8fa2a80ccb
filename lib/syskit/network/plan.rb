# frozen_string_literal: true

require 'syskit/network/plan_builder'

module Syskit
  module Network
    # The connection plan of a profile: which tasks run, deployed where,
    # configured how, connected how, in which order. A frozen value, built
    # from a generated network; renderers only read it.
    class Plan
      # A task of the plan, named after its deployed task; +devices+ are the
      # devices it drives, each followed by its slaves (+stereo.left+);
      # +unmanaged+: its deployment is started outside of Syskit;
      # +operations+: the operations its configure called, in call order;
      # +process_server+: where its deployment runs ({'name', 'host'}), when
      # the robot configuration says (+on:+), else nil.
      Task = Struct.new(:name, :model, :deployment, :devices, :conf, :properties, :ports, :depends_on, :unmanaged,
                        :operations, :process_server)
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
      # A composition of the plan, named after where it stands (a
      # definition, +definition.child+ for a composition child): its model,
      # the action it was made for (+Base.x_def+, nil for a child), its
      # arguments and sections, its children (role => task or composition
      # name), its exports (port => Endpoint of the task that has it) and
      # its parent composition's name (nil for a root).
      Composition = Struct.new(:name, :model, :action, :arguments, :conf, :children, :exports, :parent)

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
      [Task, Port, Device, Composition].each { |entry| entry.extend(ByField) }

      attr_reader :profile, :robot, :tasks, :devices, :connections, :order, :buses, :compositions

      # A plan of the network of +context+ (see Builder).
      def self.build(context)
        Builder.build(context)
      end

      def initialize(profile:, robot:, tasks:, devices:, connections:, order:, buses: [], compositions: [])
        @profile = profile.freeze
        @robot = robot.freeze
        @tasks = tasks.freeze
        @devices = devices.freeze
        @connections = connections.freeze
        @order = order.freeze
        @buses = buses.freeze
        @compositions = compositions.freeze
        freeze
      end

      def find_composition(name)
        compositions.find { |c| c.name == name }
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
      LISTS = %w[tasks devices connections order buses compositions].freeze

      # The plan as plain data, the JSON document's content.
      def to_h
        shared = {}.compare_by_identity # see #plain_entries
        LISTS.each_with_object({ 'profile' => profile, 'robot' => robot }) do |list, plain|
          plain[list] = plain_entries(list, public_send(list), shared)
        end
      end

      # +entries+ of list +list+ (one of LISTS) as plain data: hashes with
      # string keys, as in #to_h. +shared+ keeps the plain data of the
      # entries the plan shares (by entry): a port entry and a list of them
      # (the tasks of a model share their static ports), an endpoint (the
      # port of a bus driver that serves every device).
      def plain_entries(list, entries, shared = {}.compare_by_identity)
        return entries.map { |t| task_hash(t, shared) } if list == 'tasks'
        return entries.map { |c| connection_hash(c, shared) } if list == 'connections'

        hash = ENTRY_HASHES.fetch(list) { raise ArgumentError, "#{list} is not one of #{LISTS.join(', ')}" }
        entries.map { |entry| send(hash, entry) }
      end

      # The method making the plain data of an entry, by list (but tasks).
      ENTRY_HASHES = { 'devices' => :device_hash, 'order' => :step_hash, 'buses' => :bus_hash,
                       'compositions' => :composition_hash }.freeze

      private

      def task_hash(task, shared)
        operations = task.operations
        hash = {
          'name' => task.name, 'model' => task.model, 'deployment' => task.deployment,
          'devices' => task.devices, 'conf' => task.conf, 'properties' => task.properties,
          'ports' => shared[task.ports] ||= task.ports.map { |p| shared[p] ||= port_hash(p) },
          'depends_on' => task.depends_on, 'unmanaged' => task.unmanaged,
          'operations' => operations.empty? ? operations : operations.map { |op| operation_hash(op) }
        }
        hash['process_server'] = task.process_server if task.process_server
        hash
      end

      # The call; the argument names when the spec declares them, so that
      # readers of the file (plan diffs) know which are ids.
      def operation_hash(operation)
        hash = { 'name' => operation.name, 'arguments' => operation.arguments }
        names = operation.argument_names
        names.nil? || names.empty? ? hash : hash.merge('argument_names' => names)
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

      def composition_hash(composition)
        {
          'name' => composition.name, 'model' => composition.model, 'action' => composition.action,
          'arguments' => composition.arguments, 'conf' => composition.conf, 'children' => composition.children,
          'exports' => composition.exports.transform_values { |e| { 'task' => e.task, 'port' => e.port } },
          'parent' => composition.parent
        }
      end

      def connection_hash(conn, shared)
        {
          'from' => shared[conn.from] ||= endpoint_hash(conn.from),
          'to' => shared[conn.to] ||= endpoint_hash(conn.to),
          'type' => conn.type, 'policy' => conn.policy
        }
      end

      def endpoint_hash(endpoint)
        { 'task' => endpoint.task, 'port' => endpoint.port }
      end
    end
  end
end
