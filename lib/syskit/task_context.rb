# frozen_string_literal: true

require 'syskit/models/task_context'
require 'syskit/properties'
require 'syskit/task_connections'
require 'syskit/task_properties'
require 'syskit/task_event_generator'

module Syskit
  # A task of a network: an instance of a task model (a subclass of this
  # class made for each task context of a loaded .orogen file).
  #
  # The generator creates one per driver and bus, sets the +<name>_dev+
  # arguments, applies configuration sections, then calls {#configure}, which
  # users override in extension files (calling +super+ first).
  class TaskContext < Component
    extend Models::TaskContext
    include TaskConnections
    include TaskProperties

    # A task model made in Ruby, as Syskit's tests make them (see
    # Models::Component#new_submodel):
    # +Syskit::TaskContext.new_submodel { input_port 'in', '/double' }+ is
    # a RubyTaskContext; +OroGen.lib.Task.new_submodel { ... }+ a submodel
    # of that task model, with the ports and properties its block adds.
    def self.submodel_class
      return Class.new(RubyTaskContext) if equal?(TaskContext)

      RubyTaskContext.declared_in_ruby(Class.new(self), Location.of_caller)
    end
    private_class_method :submodel_class

    # Most tasks never create a port: they share this until they do.
    NO_PORTS = {}.freeze
    NO_CALLS = [].freeze
    NO_CONNECTIONS = [].freeze
    private_constant :NO_PORTS, :NO_CALLS, :NO_CONNECTIONS

    attr_reader :deployed_task

    # Whether the task is one that runs already, that Syskit only reads
    # from (a configured deployment's +read_only:+ tasks), as Syskit's
    # argument: false unless set.
    argument :read_only, default: false

    # The name the task goes by before it is deployed: its device's, or
    # its place in a composition (+arm_control_position2twist+).
    def plan_name
      requirements&.device&.name || plan_path&.tr('.', '_') || Naming.underscore(model.name.to_s.split('::').last)
    end

    def initialize(arguments = {})
      super()
      @properties = model.properties_class.initial(self)
      @created_ports = NO_PORTS
      @children = []
      @child_tasks = []
      @connections = NO_CONNECTIONS
      assign_arguments(arguments)
    end

    # The ports created at configure time, by name.
    attr_reader :created_ports

    # The deployed task name, which names the task in plans (nil until the
    # task is deployed).
    attr_reader :name

    # Syskit's name for the deployed task name (#name here, the name plans
    # show): what a test checks after syskit_deploy.
    def orocos_name
      name
    end

    # Binds the task to a deployed task of the robot configuration. The name
    # is kept here: plans, sorts and connections ask for it many times.
    def deployed_task=(deployed)
      @deployed_task = deployed
      @name = deployed&.name
    end

    # Syskit's configuration hook for properties: model files override it
    # (calling super) to set properties from the task's devices, arguments
    # or Conf. The generator runs it before #configure when the model uses
    # it (Models::TaskContext#use_update_properties?); a model that only
    # defines #configure gets it from configure's super, as in Syskit.
    def update_properties; end

    # Configuration hook: user extension files override it and call super.
    def configure
      update_properties unless model.use_update_properties?
    end

    # The host the task must run on (Syskit's +required_host+), nil when
    # any will do: two tasks bound to different hosts are not merged.
    attr_accessor :required_host

    def can_merge?(other)
      if required_host && other.respond_to?(:required_host) && other.required_host &&
         required_host != other.required_host
        return false
      end

      super
    end

    # The hints choosing its deployed task (see prefer_deployed_tasks): its
    # requirements', else those of the devices it drives, else its
    # parents' (see AbstractComponent#deployment_hints).
    def deployment_hints
      own = requirements.deployment_hints
      return own unless own.empty?

      from_devices = devices.flat_map(&:deployment_hints).uniq
      from_devices.empty? ? super : from_devices
    end

    # The event emitted when the task enters the state +name+ (see
    # Models::TaskContext#state_events), nil when it has none.
    def state_event(name)
      model.find_state_event(name)
    end

    # +abort 'message'+ in configure stops the plan with a located error
    # saying so (Kernel#abort would also print the message on its own).
    def abort(message = nil)
      raise SystemExit.new(false, message || 'exit')
    end

    # The component this task stands for (see Component): its properties
    # and operations, as configure methods and stub blocks use them.
    def orocos_task
      @orocos_task ||= model.component_class.new(self)
    end

    # The operations called on the component so far (see Component).
    def operation_calls
      @orocos_task ? @orocos_task.operation_calls : NO_CALLS
    end

    # The devices this task drives, from its +<name>_dev+ arguments.
    def devices
      @devices ||= begin
        found = []
        arguments.each_value do |value|
          found << value if value.is_a?(Robot::MasterDeviceInstance) && !found.include?(value)
        end
        found.freeze
      end
    end

    # Syskit's +task.require_dynamic_service('dyn', as: 'name')+: the
    # service +name+ of the task, made from its model's dynamic service
    # +dyn+ on the task's own model (see AbstractComponent#specialize),
    # so that other tasks of the model are left as they are. The service
    # already there is returned if it is of the dynamic service's model.
    def require_dynamic_service(dynamic_name, as:, **options)
      specialize
      model.require_dynamic_service(dynamic_name, as: as, **options)
      # A lookup made before the service existed found none.
      @bound_services.delete(as.to_s) if @bound_services && !@bound_services[as.to_s]
      # Its reader, on this task alone (+task.rear_srv+).
      reader = "#{as}_srv"
      define_singleton_method(reader) { find_data_service(as) } unless respond_to?(reader)
      find_data_service(as)
    end

    # The services made for this task from dynamic services, as Syskit's
    # required dynamic services (Syskit::BoundDataService, their options in
    # +srv.model.dynamic_service_options+): those its model requires (a
    # specialization's, see Models::DynamicServices#require_dynamic_service)
    # and its devices' slaves declared from one.
    def each_required_dynamic_service(&block)
      return enum_for(__method__).to_a unless block

      super
      devices.each do |device|
        device.each_slave { |slave| yield slave.service.bind(self) if slave.dynamic_service_name && slave.service }
      end
    end

    # The device this task drives, when it drives only one.
    def robot_device
      found = devices
      return found.first if found.size == 1

      raise ConfigurationError.new(
        "#{model.name} drives #{found.size} devices (#{found.map(&:name).join(', ')}), robot_device needs exactly one",
        location: Location.of_caller, hint: 'use the <name>_dev reader of the driver_for service instead'
      )
    end

    # On a bus driver: every device declared on its bus, in declaration order.
    def each_declared_attached_device(&)
      bus = devices.find(&:com_bus?)
      unless bus
        raise ConfigurationError.new("#{model.name} drives no communication bus",
                                     location: Location.of_caller,
                                     hint: 'each_declared_attached_device is for bus drivers')
      end

      bus.each_attached_device(&)
    end

    # The tasks this one depends on (its bus drivers), as +[task, info]+ pairs.
    def each_child(&block)
      return enum_for(__method__) unless block

      @children.each(&block)
    end

    # The tasks this one depends on.
    def children
      @child_tasks
    end

    def add_child(task, info = {})
      return if @child_tasks.any? { |t| t.equal?(task) }

      @children << [task, info]
      @child_tasks << task
    end

    # Static ports and ports created at configure time, by name.
    def ports
      model.ports.merge(created_ports)
    end

    # What the oroGen model (or the pattern the port was created from)
    # declares of the port +name+ (Orogen::Port), nil when there is none.
    def find_orogen_port(name)
      created_ports[name.to_s] || model.ports[name.to_s]
    end

    # The port +name+ of this task (+task.out_port+), which knows what it
    # is connected to in the network; nil when there is no such port.
    def find_port(name)
      port = find_orogen_port(name)
      Port.new(Models::Port.for(model, port), self) if port
    end

    # Its ports (see #find_port), static and created.
    def each_port
      return enum_for(__method__) unless block_given?

      ports.each_key { |name| yield find_port(name) }
    end

    # A port of this task is its own component port (Syskit's name).
    def self_port_to_component_port(port)
      port
    end

    # The connections of the network that start or end at this task.
    attr_reader :connections

    def add_connection(connection)
      @connections = [] if @connections.frozen?
      @connections << connection
    end

    # Creates a port the task model declares a dynamic pattern for.
    def create_port(direction, name, type, location: nil)
      name = name.to_s
      type = Models.resolve_type(type, location)
      if (existing = find_orogen_port(name))
        return existing if existing.direction == direction && existing.type == type

        raise NetworkError.new("#{self} already has an #{existing}, cannot create an #{direction} port " \
                               "of type #{type} with the same name", location: location)
      end

      pattern = model.spec&.dynamic_port_for(direction, name, type)
      raise no_dynamic_port(direction, name, type, location) unless pattern

      @created_ports = {} if @created_ports.frozen?
      @created_ports[name] = pattern.instantiate(name, type)
    end

    def to_s
      name ? "#{model.name} '#{name}'" : model.name.to_s
    end

    def inspect
      "#<#{self}>"
    end

    # The events of RTT's states, which every task has.
    define_event_readers

    private

    def no_dynamic_port(direction, name, type, location)
      patterns = model.dynamic_ports.select { |p| p.direction == direction }
      known = patterns.empty? ? "it declares no dynamic #{direction} ports" : "its patterns are #{patterns.join(', ')}"
      NetworkError.new(
        "#{model.name} cannot create #{direction} port '#{name}' (#{type}): #{known}",
        location: location,
        hint: "declare a matching pattern in the .orogen file, e.g. dynamic_#{direction}_port(/^\\w+$/, '#{type}')"
      )
    end
  end
end
