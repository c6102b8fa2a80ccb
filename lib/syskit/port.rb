# frozen_string_literal: true

module Syskit
  # What a port declaration says about the connections it wants. Shared by
  # ports and dynamic port patterns (a created port inherits its pattern's).
  module ConnectionNeeds
    NEEDS = %i[doc multiplexes reliable buffer_size period burst sample_size].freeze
    SETTERS = NEEDS.to_h { |attr| [attr, :"#{attr}="] }.freeze

    attr_accessor(*NEEDS)

    def multiplexes?
      !!multiplexes
    end

    # oroGen's +static+: the port's connections are set before the task is
    # configured, so changing them needs a reconfiguration.
    attr_writer :static

    def static?
      !!@static
    end

    # Whether a connection into this port must not lose samples.
    def reliable?
      !!reliable
    end

    def input?
      direction == :input
    end

    def output?
      direction == :output
    end

    def copy_needs_from(other)
      SETTERS.each { |attr, setter| public_send(setter, other.public_send(attr)) }
      self.static = other.static?
      self
    end
  end

  # A port of a task (+task.out_port+): its model (a Models::Port of the
  # task's model) and the task (+component+). It tells what it is
  # connected to, and connects to another task's port as plan data.
  class Port
    attr_reader :model, :component

    def initialize(model, component)
      @model = model
      @component = component
    end

    def name
      model.name
    end

    def type
      model.type
    end

    # The type as declared (see Orogen::Port#type_description).
    def type_description
      model.type_description
    end

    def direction
      model.direction
    end

    def input?
      model.input?
    end

    def output?
      model.output?
    end

    # The port of the task itself this port stands for (this one on a
    # task); ArgumentError when the component cannot say.
    def to_component_port
      return component.self_port_to_component_port(self) if component.respond_to?(:self_port_to_component_port)

      raise ArgumentError, "cannot resolve #{self} into a component port: #{component} has no ports of its own"
    end

    # The port of the task that has it (Syskit's +to_actual_port+): this
    # one, a composition's port being found on the child it exports.
    def to_actual_port
      return self unless component.respond_to?(:resolve_export)

      component.find_port(name)&.to_actual_port || self
    end

    # Connects this output port to +sink+, an input port of another task
    # of the same type: both tasks then know the connection (as the
    # network's connections), with the policy given.
    def connect_to(sink, policy = {})
      location = Location.of_caller
      source = to_component_port
      sink = sink.to_component_port
      check_connection(source, sink, location)
      connection = Network::Connect::Connection.new(source.component, source.model.orogen_port, sink.component,
                                                    sink.model.orogen_port, policy, nil, location)
      source.component.add_connection(connection)
      sink.component.add_connection(connection)
      self
    end

    # Whether a connection of the network links this port and +other+ (a
    # task's port), in either direction, or one of a composition both
    # tasks are children of (as tasks instanciated from models are, before
    # a network is made of them).
    def connected_to?(other)
      source = to_component_port
      other = other.to_component_port
      return true if source.component.connections.any? { |c| source.links?(c, other) || other.links?(c, source) }

      source.component.each_parent_task.any? { |cmp| cmp.connects?(source, other) || cmp.connects?(other, source) }
    end

    def ==(other)
      other.is_a?(Port) && other.component.equal?(component) && other.model == model
    end
    alias eql? ==

    def hash
      [Port, component.object_id, name].hash
    end

    def to_s
      "#{component}.#{name}_port"
    end
    alias inspect to_s

    protected

    # Whether +connection+ goes from this port to +sink+.
    def links?(connection, sink)
      connection.from_task.equal?(component) && connection.from_port.name == name &&
        connection.to_task.equal?(sink.component) && connection.to_port.name == sink.name
    end

    private

    def check_connection(source, sink, location)
      same = sink.respond_to?(:component) && source.component.equal?(sink.component)
      PortConnectionCheck.check!(source, sink, location, same_owner: same, owner: 'task')
    end
  end

  # A pattern of ports a task can create at configure time
  # (+dynamic_output_port(/\w+/, '/canbus/Message')+).
  class DynamicPort
    include ConnectionNeeds

    attr_reader :pattern, :direction, :type

    def initialize(pattern, direction, type)
      @pattern = pattern
      @direction = direction
      @type = type
    end

    # A pattern without a type (oroGen's dynamic ports of any type) matches
    # every type.
    def match?(port_name, port_type)
      pattern.match?(port_name) && (type.nil? || port_type == type)
    end

    # The concrete port this pattern gives for +port_name+ (of +port_type+
    # for a pattern of any type).
    def instantiate(port_name, port_type = type)
      Orogen::Port.new(port_name, direction, type || port_type, dynamic: true).copy_needs_from(self)
    end

    def to_s
      "dynamic #{direction} port #{pattern.inspect} (#{type ? type.name : 'any type'})"
    end
  end

  # The modifiers oroGen accepts after a port declaration, e.g.
  # +input_port('in', '/canbus/Message').multiplexes.needs_reliable_connection+.
  class PortModifiers
    def initialize(port)
      @port = port
    end

    # Views of the same port are equal.
    def ==(other)
      other.is_a?(PortModifiers) && other.port.equal?(port)
    end

    protected

    attr_reader :port

    public

    # The port this is a view of (see Models::Port#orogen_port).
    def orogen_port
      @port
    end

    # The port's own readers, for code that looked the port up.
    def name
      @port.respond_to?(:name) ? @port.name : @port.pattern
    end

    def type
      @port.type
    end

    def multiplexes
      @port.multiplexes = true
      self
    end

    def static
      @port.static = true
      self
    end

    def needs_reliable_connection
      @port.reliable = true
      self
    end

    def needs_buffered_connection(size = 1)
      @port.buffer_size = Integer(size)
      self
    end

    def doc(text)
      @port.doc = text
      self
    end

    def period(seconds)
      @port.period = seconds
      self
    end

    def burst(count, _period = nil)
      @port.burst = count
      self
    end

    def sample_size(size)
      @port.sample_size = size
      self
    end

    # Accepted and recorded by oroGen, meaningless for planning.
    %i[needs_data_connection keep_last_written_value default_policy
       triggered_on triggered_on_update max_sizes task_trigger trigger_port triggered_once_per_update].each do |name|
      define_method(name) { |*_args, **_kwargs| self }
    end
  end
end
