# frozen_string_literal: true

module Syskit
  module Models
    # Binds the ports of a service model to the ports of a task model, for
    # +provides+ and +driver_for+: explicit mappings first, then same name and
    # type, then the only port of the same type and direction.
    class PortMapper
      def initialize(task_model, srv_model, mappings, location)
        @task_model = task_model
        @srv_model = srv_model
        @explicit = Models.normalize_mappings(srv_model, mappings, location, owner: task_model.name)
        @location = location
      end

      # +{service port name => task port name}+; raises when a port has no
      # match or several.
      def map
        @srv_model.ports.each_value.to_h { |port| [port.name, task_port_for(port).name] }
      end

      private

      def task_port_for(srv_port)
        if (name = @explicit[srv_port.name])
          return explicit_port(srv_port, name)
        end

        same_name = @task_model.find_port(srv_port.name)
        return same_name if compatible?(same_name, srv_port)

        candidates = @task_model.ports.values.select { |p| compatible?(p, srv_port) }
        return candidates.first if candidates.size == 1

        raise candidates.empty? ? no_port(srv_port) : ambiguous(srv_port, candidates)
      end

      def compatible?(task_port, srv_port)
        task_port && task_port.direction == srv_port.direction && task_port.type == srv_port.type
      end

      def explicit_port(srv_port, name)
        port = @task_model.find_port(name)
        return port if compatible?(port, srv_port)

        problem = port ? "is an #{port}" : 'does not exist'
        raise DeclarationError.new(
          "#{@task_model.name}'s port '#{name}', mapped to #{@srv_model}'s #{srv_port}, #{problem}",
          location: @location, hint: "map '#{srv_port.name}' to an #{srv_port.direction} port of type " \
                                     "#{srv_port.type}#{port_list(srv_port)}"
        )
      end

      def no_port(srv_port)
        DeclarationError.new(
          "#{@task_model.name} has no #{srv_port.direction} port of type #{srv_port.type} " \
          "for #{@srv_model}'s port '#{srv_port.name}'",
          location: @location,
          hint: "add the port to the task's .orogen declaration or map it: '#{srv_port.name}' => 'task_port'"
        )
      end

      def ambiguous(srv_port, candidates)
        names = candidates.map(&:name).sort
        DeclarationError.new(
          "#{@task_model.name} has several #{srv_port.direction} ports of type #{srv_port.type} " \
          "for #{@srv_model}'s port '#{srv_port.name}': #{names.join(', ')}",
          location: @location, hint: "choose one explicitly: '#{srv_port.name}' => '#{names.first}'"
        )
      end

      def port_list(srv_port)
        names = @task_model.ports.values.select { |p| compatible?(p, srv_port) }.map(&:name)
        names.empty? ? '' : " (#{names.sort.join(', ')})"
      end
    end
  end
end
