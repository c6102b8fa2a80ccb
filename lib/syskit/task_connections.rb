# frozen_string_literal: true

module Syskit
  # Syskit's data-flow edits between two tasks held in a plan, by port
  # names: +source.connect_ports(sink, ['out', 'in'] => policy)+ and
  # +source.disconnect_ports(sink, [['out', 'in']])+. Both check every
  # pair before changing anything. Part of TaskContext.
  module TaskConnections
    # Connects, for each +[output, input] => policy+ of +mappings+, the
    # output port of this task to the input port of +sink_task+.
    def connect_ports(sink_task, mappings)
      location = Location.of_caller
      pairs = mappings.map do |(out_name, in_name), policy|
        [connected_port(:output, out_name, location), sink_task.connected_port(:input, in_name, location), policy]
      end
      pairs.each { |source, sink, policy| source.connect_to(sink, policy || {}) }
      self
    end

    # Removes, for each +[output, input]+ of +mappings+, the connection
    # from the output port of this task to the input port of +sink_task+:
    # an ArgumentError if a port or a connection is not there.
    def disconnect_ports(sink_task, mappings)
      location = Location.of_caller
      removed = mappings.map do |out_name, in_name|
        source = connected_port(:output, out_name, location)
        sink = sink_task.connected_port(:input, in_name, location)
        connection_between(source, sink, location)
      end
      [self, sink_task].each { |task| task.remove_connections(removed) }
      self
    end

    # Its port +name+ of +direction+ (a Syskit::Port), or an
    # InvalidArgument located at +location+.
    def connected_port(direction, name, location)
      port = find_port(name)
      return port if port && port.direction == direction

      known = ports.values.select { |p| p.direction == direction }.map(&:name).sort
      raise InvalidArgument.new("#{self} has no #{direction} port '#{name}'#{Naming.did_you_mean(name.to_s, known)}",
                                location: location, hint: "its #{direction} ports: #{known.join(', ')}")
    end

    # Forgets +removed+ (connections of the network).
    def remove_connections(removed)
      @connections = connections.reject { |c| removed.any? { |r| r.equal?(c) } }.freeze
    end

    private

    def connection_between(source, sink, location)
      found = connections.find do |c|
        c.from_task.equal?(self) && c.from_port.name == source.name &&
          c.to_task.equal?(sink.component) && c.to_port.name == sink.name
      end
      return found if found

      raise InvalidArgument.new("#{source} is not connected to #{sink}",
                                location: location, hint: 'disconnect_ports removes what connect_ports made')
    end
  end
end
