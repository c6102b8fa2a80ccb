# frozen_string_literal: true

module Syskit
  module Models
    # Binds the ports of a service model to the ports of a task model, for
    # +provides+ and +driver_for+: explicit mappings first, then same name and
    # type, then the only port of the same type and direction. As in Syskit,
    # service ports bound to one task port must all be mapped explicitly.
    #
    # In a dynamic service (+dynamic: true+), an explicit mapping may name a
    # port the task does not have yet but can create (a dynamic_*_port
    # pattern of the right direction and type): see #created.
    class PortMapper
      # +error_class+: what a mapping that cannot be made raises
      # (InvalidProvides for a declaration, InvalidPortMapping for Syskit's
      # +compute_port_mappings+).
      def initialize(task_model, srv_model, mappings, location, dynamic: false, error_class: InvalidProvides)
        @task_model = task_model
        @srv_model = srv_model
        @error_class = error_class
        @explicit = Models.normalize_mappings(srv_model, mappings, location,
                                              owner: task_model.name, error_class: error_class)
        @location = location
        @dynamic = dynamic
        @created = []
      end

      # The ports a dynamic service's mappings need created, once #map ran.
      attr_reader :created

      # +{service port name => task port name}+; raises when a port has no
      # match or several.
      def map
        mapping = @srv_model.ports.each_value.to_h { |port| [port.name, task_port_for(port).name] }
        check_shared_ports(mapping)
        mapping
      end

      private

      def task_port_for(srv_port)
        if (name = @explicit[srv_port.name])
          return explicit_port(srv_port, name)
        end

        same_name = @task_model.ports[srv_port.name]
        return same_name if compatible?(same_name, srv_port)

        candidates = @task_model.ports.values.select { |p| compatible?(p, srv_port) }
        return candidates.first if candidates.size == 1

        raise candidates.empty? ? no_port(srv_port) : ambiguous(srv_port, candidates)
      end

      def compatible?(task_port, srv_port)
        task_port && task_port.direction == srv_port.direction && task_port.type == srv_port.type
      end

      def explicit_port(srv_port, name)
        port = @task_model.ports[name]
        return port if compatible?(port, srv_port)
        return create(srv_port, name) if !port && @dynamic && dynamic_pattern(srv_port, name)

        problem = port ? "is an #{port}" : 'does not exist'
        raise @error_class.new(
          "#{@task_model.name}'s port '#{name}', mapped to #{@srv_model}'s #{srv_port}, #{problem}",
          location: @location, hint: "map '#{srv_port.name}' to an #{srv_port.direction} port of type " \
                                     "#{srv_port.type}#{port_list(srv_port)}"
        )
      end

      def dynamic_pattern(srv_port, name)
        @task_model.spec&.dynamic_port_for(srv_port.direction, name, srv_port.type)
      end

      def create(srv_port, name)
        port = dynamic_pattern(srv_port, name).instantiate(name)
        @created << port
        port
      end

      # Several service ports may share a task port only when each was
      # mapped on purpose.
      def check_shared_ports(mapping)
        mapping.group_by(&:last).each do |task_port, pairs|
          next if pairs.size == 1 || pairs.all? { |srv_port, _| @explicit.key?(srv_port) }

          names = pairs.map(&:first).sort
          raise @error_class.new(
            "#{@srv_model}'s ports #{names.join(', ')} would all be bound to #{@task_model.name}'s port " \
            "'#{task_port}'",
            location: @location,
            hint: "to share it, map each of them: #{names.map { |n| "'#{n}' => '#{task_port}'" }.join(', ')}"
          )
        end
      end

      def no_port(srv_port)
        pointer = pointer_port(srv_port)
        return pointer_mismatch(srv_port, pointer) if pointer

        same_direction = @task_model.ports.values.select { |p| p.direction == srv_port.direction }
        listed = same_direction.sort_by(&:name).map { |p| "#{p.name} (#{p.type})" }
        @error_class.new(
          "#{@task_model.name} has no #{srv_port.direction} port of type #{srv_port.type} " \
          "for #{@srv_model}'s port '#{srv_port.name}'" \
          "#{"; its #{srv_port.direction} ports: #{listed.join(', ')}" unless listed.empty?}",
          location: @location,
          hint: "add the port to the task's .orogen declaration or map it: '#{srv_port.name}' => 'task_port'"
        )
      end

      # A task port that holds the service port's type behind oroGen's
      # read-only pointer (ro_ptr), or the other way round.
      def pointer_port(srv_port)
        wanted = [srv_port.type.to_s, pointer_of(srv_port.type)]
        @task_model.ports.values.find do |p|
          next false unless p.direction == srv_port.direction

          wanted.include?(p.type.to_s) || pointer_of(p.type) == srv_port.type.to_s
        end
      end

      def pointer_of(type)
        "#{Types::Registry::RO_PTR}<#{type}>"
      end

      def pointer_mismatch(srv_port, task_port)
        pointer = task_port.type.to_s.start_with?(Types::Registry::RO_PTR)
        fix = if pointer
                "declare #{@srv_model}'s port '#{srv_port.name}' with ro_ptr('#{srv_port.type}'), as the task's is"
              else
                "declare #{@srv_model}'s port '#{srv_port.name}' as a plain '#{task_port.type}', as the task's is"
              end
        @error_class.new(
          "#{@task_model.name}'s #{task_port.direction} port '#{task_port.name}' is a #{task_port.type}, " \
          "not the #{srv_port.type} of #{@srv_model}'s port '#{srv_port.name}'",
          location: @location, hint: "#{fix} (ro_ptr(T) and T are different types to Syskit)"
        )
      end

      def ambiguous(srv_port, candidates)
        names = candidates.map(&:name).sort
        @error_class.new(
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
