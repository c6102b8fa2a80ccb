# frozen_string_literal: true

module Syskit
  module Network
    # Step 6: connects each attached device's driver and its bus driver
    # (bus '<device>' -> device, device -> bus input) and the children of
    # each composition, with their policies, and refuses several writers
    # on an input that does not multiplex.
    class Connect
      # A connection between two ports; +device+: the attached device of a
      # bus link (nil for a composition's connection), +location+: where
      # the connection is declared.
      Connection = Struct.new(:from_task, :from_port, :to_task, :to_port, :policy, :device, :location)

      def initialize(context)
        @context = context
      end

      def run
        @context.bus_links.each do |link|
          if link.bus_output
            connect(link.bus_task, link.bus_output, link.device_task, link.client_input,
                    device: link.device, into_bus: false)
          end
          if link.bus_input
            connect(link.device_task, link.client_output, link.bus_task, link.bus_input,
                    device: link.device, into_bus: true)
          end
        rescue Syskit::Error => e
          @context.error(e)
        end
        seen = {}
        @context.compositions.each { |composition| connect_children(composition, seen) }
        check_multiplexing
      end

      private

      def connect(from_task, from_name, to_task, to_name, device:, into_bus:)
        from = port(from_task, from_name, :output, device)
        to = port(to_task, to_name, :input, device)
        unless from.type == to.type
          raise NetworkError.new("cannot connect #{from_task}'s #{from} to #{to_task}'s #{to}: types differ",
                                 location: device.declared_at, hint: 'both ports must have the bus message type')
        end

        policy = Policy.for(to, to_task, device, into_bus: into_bus)
        add(Connection.new(from_task, from, to_task, to, policy, device, device.declared_at))
      end

      def add(connection)
        @context.connections << connection
        connection.from_task.add_connection(connection)
        connection.to_task.add_connection(connection)
      end

      # The connections a composition declares between its children, from
      # the port that has the data to the port that takes it (through the
      # exports of children that are compositions). Children left out
      # (optional ones nothing was selected for) have no connections. A
      # connection two compositions declare between the same (merged)
      # tasks is made once.
      def connect_children(composition, seen)
        composition.model.port_connections.each do |declared|
          from = composition.resolve_child_port(declared.from)
          to = composition.resolve_child_port(declared.to)
          next unless from && to

          # One list per connection (task, port name, task, port name, by
          # identity): +from+ and +to+ are [task, port name] pairs.
          key = [from[0].object_id, from[1].object_id, to[0].object_id, to[1].object_id]
          next if seen[key]

          seen[key] = true
          add(composition_connection(from, to, declared))
        rescue Syskit::Error => e
          @context.error(e)
        end
      end

      def composition_connection(from, to, declared)
        from_port = port_of(from[0], from[1], :output, declared)
        to_port = port_of(to[0], to[1], :input, declared)
        policy = declared.policy
        policy = policy.empty? ? Policy.for_port(to_port) : Policy.declared(Policy.of(policy), to_port)
        Connection.new(from[0], from_port, to[0], to_port, policy, nil, declared.location)
      end

      def port_of(task, name, direction, declared)
        port = task.find_orogen_port(name)
        return port if port&.direction == direction

        raise NetworkError.new("#{task} has no #{direction} port '#{name}' for the connection declared here",
                               location: declared.location,
                               hint: 'the component selected for the child does not have the port the ' \
                                     'connection names: select one that provides it')
      end

      def port(task, name, direction, device)
        port = task.find_orogen_port(name)
        return port if port&.direction == direction

        raise NetworkError.new("#{task} has no #{direction} port '#{name}' for #{device}",
                               location: device.declared_at,
                               hint: 'the port should have been created at configure time')
      end

      # Only the connections into a port written more than once are
      # gathered, to report them.
      def check_multiplexing
        writers = writer_counts
        shared = @context.connections.select do |c|
          counts = writers[c.to_task]
          counts && counts[c.to_port.name] > 1 && !c.to_port.multiplexes?
        end
        shared.group_by { |c| [c.to_task, c.to_port.name] }.each_value do |into|
          @context.error(multiplexing_error(into))
        end
      end

      # How many connections write to each input port, by task and port
      # name, on the tasks written to more than once (nil for the others:
      # most tasks have one input connected, they get no hash each).
      def writer_counts
        by_task = Hash.new(0).compare_by_identity
        @context.connections.each { |c| by_task[c.to_task] += 1 }
        writers = {}.compare_by_identity
        @context.connections.each do |c|
          (writers[c.to_task] ||= Hash.new(0))[c.to_port.name] += 1 if by_task[c.to_task] > 1
        end
        writers
      end

      # +into+: the connections that write to one input port.
      def multiplexing_error(into)
        sink = into.first
        sources = into.map { |c| "#{c.from_task.name}.#{c.from_port.name} (#{c.device || c.location})" }
        NetworkError.new(
          "#{sink.to_task}'s input port '#{sink.to_port.name}' does not multiplex but " \
          "#{into.size} outputs write to it: #{sources.join(', ')}",
          location: into.last.location,
          hint: 'mark it .multiplexes in the .orogen file if the component accepts several writers, ' \
                'or give each device its own input port (dynamic_input_port)'
        )
      end
    end
  end
end
