# frozen_string_literal: true

module Syskit
  module Network
    # Step 6: connects each attached device's driver and its bus driver
    # (bus '<device>' -> device, device -> bus input) with their policies,
    # and refuses several writers on an input that does not multiplex.
    class Connect
      # A connection between two ports.
      Connection = Struct.new(:from_task, :from_port, :to_task, :to_port, :policy, :device)

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
        @context.connections << Connection.new(from_task, from, to_task, to, policy, device)
      end

      def port(task, name, direction, device)
        port = task.find_port(name)
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
          writers[c.to_task][c.to_port.name] > 1 && !c.to_port.multiplexes?
        end
        shared.group_by { |c| [c.to_task, c.to_port.name] }.each_value do |into|
          @context.error(multiplexing_error(into))
        end
      end

      # How many connections write to each input port, by task and port name.
      def writer_counts
        writers = Hash.new { |h, task| h[task] = Hash.new(0) }.compare_by_identity
        @context.connections.each { |c| writers[c.to_task][c.to_port.name] += 1 }
        writers
      end

      # +into+: the connections that write to one input port.
      def multiplexing_error(into)
        sink = into.first
        sources = into.map { |c| "#{c.from_task.name}.#{c.from_port.name} (#{c.device})" }
        NetworkError.new(
          "#{sink.to_task}'s input port '#{sink.to_port.name}' does not multiplex but " \
          "#{into.size} outputs write to it: #{sources.join(', ')}",
          location: into.last.device.declared_at,
          hint: 'mark it .multiplexes in the .orogen file if the component accepts several writers, ' \
                'or give each device its own input port (dynamic_input_port)'
        )
      end
    end
  end
end
