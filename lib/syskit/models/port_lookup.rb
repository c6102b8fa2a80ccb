# frozen_string_literal: true

module Syskit
  module Models
    # Syskit's port lookups on anything that has its ports by name in
    # +ports+ (data services, task and composition models, children).
    module PortLookup
      def find_port(name)
        ports[name.to_s]
      end

      def find_output_port(name)
        port = find_port(name)
        port if port&.output?
      end

      def find_input_port(name)
        port = find_port(name)
        port if port&.input?
      end

      def has_port?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        ports.key?(name.to_s)
      end

      def has_input_port?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        !find_input_port(name).nil?
      end

      def has_output_port?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        !find_output_port(name).nil?
      end

      def each_port(&)
        ports.each_value(&)
      end

      # Its input (output) ports, in declaration order.
      def each_input_port(&)
        ports.each_value.select(&:input?).each(&)
      end

      def each_output_port(&)
        ports.each_value.select(&:output?).each(&)
      end
    end

    # Syskit's port lookups on task and data service models: the
    # Models::Port of this model (which takes oroGen's port modifiers:
    # +find_output_port('pose').triggered_once_per_update+); nil when there
    # is no such port. (+find_port+ and +ports+ give the declarations.)
    module PortModelLookups
      # The port +name+ of this model (a Models::Port, the same object
      # each time), nil when there is none. Its declaration is
      # +ports[name]+.
      def find_port(name)
        port = ports[name.to_s]
        port && port_model(port)
      end

      def find_output_port(name)
        port = ports[name.to_s]
        port_model(port) if port&.output?
      end

      def find_input_port(name)
        port = ports[name.to_s]
        port_model(port) if port&.input?
      end

      # Its ports (input, output), in declaration order.
      def each_port(&)
        return enum_for(__method__) unless block_given?

        ports.each_value { |port| yield port_model(port) }
      end

      def each_input_port(&)
        return enum_for(__method__) unless block_given?

        ports.each_value { |port| yield port_model(port) if port.input? }
      end

      def each_output_port(&)
        return enum_for(__method__) unless block_given?

        ports.each_value { |port| yield port_model(port) if port.output? }
      end

      private

      # The Models::Port of the declaration +port+: one per declaration, so
      # that a port read twice is the same object (+assert_same
      # task_m.out_port, task_m.find_output_port('out')+), as in Syskit.
      def port_model(port)
        (@port_models ||= {}.compare_by_identity)[port] ||= Port.for(self, port)
      end
    end
  end
end
