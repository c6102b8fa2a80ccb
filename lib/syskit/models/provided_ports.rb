# frozen_string_literal: true

module Syskit
  module Models
    # The ports a model takes from a model it provides (+provides Pose,
    # 'pose' => 'odometry'+), checked as Syskit checks them:
    #
    # - a mapped port binds the provided port to a port the model already
    #   has, of the same direction and type; a mapping never makes a port;
    # - an unmapped port is added to the model under its own name, unless
    #   the model has a port of that name: then the user must say it is the
    #   same port ('pose' => 'pose') or map it to another one, even when
    #   both have the same type.
    #
    # A port that breaks these rules is a SpecError, as in Syskit.
    class ProvidedPorts
      def initialize(model, provided, renames, location)
        @model = model
        @provided = provided
        @renames = renames
        @location = location
      end

      # +{provided port name => model port name}+, adding the unmapped ports
      # to the model once every port is known to be valid.
      def adopt
        added = []
        mapping = @provided.ports.each_value.to_h do |port|
          if (name = @renames[port.name])
            check_mapped(port, name)
          else
            check_unmapped(port)
            added << port
            name = port.name
          end
          [port.name, name]
        end
        added.each do |port|
          @model.add_port_entry(Orogen::Port.new(port.name, port.direction, port.type,
                                                 declared_type: port.declared_type))
        end
        mapping
      end

      private

      def check_mapped(port, name)
        target = @model.ports[name]
        unless target
          raise SpecError.new(
            "#{@model} has no port '#{name}' to map #{@provided}'s #{port} to",
            location: @location,
            hint: "declare it before the provides statement (#{port.direction}_port '#{name}', " \
                  "'#{port.type}'), or leave '#{port.name}' unmapped to take the port as it is"
          )
        end
        return if target.direction == port.direction && target.type == port.type

        raise SpecError.new(
          "#{@provided}'s #{port} cannot be mapped to #{@model}'s #{target}",
          location: @location, hint: "map '#{port.name}' to an #{port.direction} port of type #{port.type}"
        )
      end

      def check_unmapped(port)
        existing = @model.ports[port.name]
        return unless existing

        other = "map it to another port: provides #{@provided}, '#{port.name}' => 'other_name'"
        if existing.direction == port.direction && existing.type == port.type
          other = "if they are the same port, say so: provides #{@provided}, '#{port.name}' => '#{port.name}'; " \
                  "else #{other}"
        end
        raise SpecError.new("#{@provided}'s #{port} collides with #{@model}'s #{existing}",
                            location: @location, hint: other)
      end
    end
  end
end
