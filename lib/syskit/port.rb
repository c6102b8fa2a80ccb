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
      self
    end
  end

  # A port of a task in a generated network (+task.out_port+): it tells
  # what it is connected to.
  class BoundPort
    attr_reader :task, :port

    def initialize(task, port)
      @task = task
      @port = port
    end

    def name
      port.name
    end

    def type
      port.type
    end

    def direction
      port.direction
    end

    # Whether a connection of the network links this port and +other+ (a
    # bound port), in either direction.
    def connected_to?(other)
      task.connections.any? do |c|
        (c.from_task.equal?(task) && c.from_port.name == name && c.to_task.equal?(other.task) &&
          c.to_port.name == other.name) ||
          (c.to_task.equal?(task) && c.to_port.name == name && c.from_task.equal?(other.task) &&
            c.from_port.name == other.name)
      end
    end

    # The component's own port: this one (a service's port readers give
    # the task's ports already, see BoundDataService).
    def to_component_port
      self
    end

    def ==(other)
      other.is_a?(BoundPort) && other.task.equal?(task) && other.name == name
    end

    def to_s
      "#{task}.#{name}_port"
    end
    alias inspect to_s
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
