# frozen_string_literal: true

module Syskit
  module Orogen
    # A task model's .orogen declaration as extension files reach it through
    # +orogen_model+ (Syskit's name): its name, ports and properties, and
    # port modifiers as in the .orogen file.
    class ModelView
      def initialize(spec)
        @spec = spec
      end

      def name
        @spec.name
      end

      # The port called +name+, with oroGen's modifiers (+.multiplexes+...),
      # nil when there is none.
      def find_port(name)
        port = @spec.find_port(name)
        PortModifiers.new(port) if port
      end

      def each_port(&)
        @spec.all_ports.each_value(&)
      end

      def find_property(name)
        @spec.all_properties[name.to_s]
      end

      def to_s
        name
      end
    end
  end
end
