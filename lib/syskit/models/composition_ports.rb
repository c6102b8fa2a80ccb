# frozen_string_literal: true

require 'syskit/models/port_lookup'

module Syskit
  module Models
    # The dataflow of composition models: the ports a composition exports
    # (its own ports are its children's, +export controller_child.cmd_port,
    # as: 'cmd'+) and the connections between its children. Part of
    # Composition.
    module CompositionPorts
      include PortLookup

      # A port of a child that the composition exports under +name+.
      Export = Struct.new(:name, :port, :location)
      # A connection between two children's ports, with its policy.
      Connection = Struct.new(:from, :to, :policy, :location)

      # Exports +port+ (a port of a child) as a port of the composition,
      # under its own name or +as+.
      def export(port, as: nil)
        location = Location.of_caller
        unless port.is_a?(ChildPort) && child_port?(port)
          raise DeclarationError.new("export expects a port of a child of #{self}, got #{Arguments.shown(port)}",
                                     location: location,
                                     hint: 'write export child_name_child.port_name_port (as: \'new_name\')')
        end

        name = (as || port.name).to_s
        existing = exports[name]
        if existing
          return find_port(name) if existing.port.same_port?(port)

          raise DeclarationError.new(
            "#{self} already exports #{existing.port} as '#{name}' (#{existing.location})",
            location: location, hint: "export #{port} under another name with as: 'other_name'"
          )
        end

        (@exports ||= {})[name] = Export.new(name, port, location)
        Component.declarations_changed
        define_port_reader(name)
        find_port(name)
      end

      # Exported ports by name, inherited ones included, each a port of the
      # child as this model has it (overloaded or not). Kept (frozen) until
      # a declaration changes (an export, a child), as #port_connections.
      def exports
        cached(:exports) do
          inherited = superclass.respond_to?(:exports) ? superclass.exports : {}
          inherited.merge(@exports || {}).transform_values do |export|
            port = current_port(export.port)
            port.equal?(export.port) ? export : Export.new(export.name, port, export.location)
          end.freeze
        end
      end

      def exported_inputs
        exports.select { |_, e| e.port.input? }.transform_values(&:port)
      end

      def exported_outputs
        exports.select { |_, e| e.port.output? }.transform_values(&:port)
      end

      def each_exported_input(&)
        exported_inputs.each(&)
      end

      def each_exported_output(&)
        exported_outputs.each(&)
      end

      def find_exported_input(name)
        exported_inputs[name.to_s]
      end

      def find_exported_output(name)
        exported_outputs[name.to_s]
      end

      def exported_port?(port)
        exports.each_value.any? { |e| e.port.same_port?(port) }
      end

      # The composition's ports (its exports), as ports of a component:
      # each keeps the oroGen port of the child port it exports, under the
      # exported name.
      def ports
        cached(:ports) do
          exports.transform_values do |e|
            (e.port.input? ? InputPort : OutputPort).new(self, e.port.orogen_model, e.name)
          end.freeze
        end
      end

      # Compositions are not oroGen components.
      def spec; end

      # Whether +port+ is a port of a child of this composition (or of one
      # of the models it refines).
      def child_port?(port)
        port.respond_to?(:composition_model) && fullfills?(port.composition_model) && !port.child.reached_through
      end

      # Syskit's +connect(out_port => in_port, ...)+ form.
      def connect(mappings)
        policy = mappings.select { |k, _| k.is_a?(Symbol) || k.is_a?(String) }
        mappings.each do |from, to|
          next if policy.key?(from)

          from.connect_to(to, policy)
        end
      end

      # Records a connection from +from+ to +to+ (ports of children),
      # checked for directions, types and owners.
      def add_connection(from, to, policy, location)
        check_grandchild_port(from, location)
        check_connection(from, to, location)
        (@connections ||= []) << Connection.new(from, to, policy, location)
        Component.declarations_changed
        self
      end

      # The connections between children, one per pair of ports (a
      # Connection, which knows where it was declared), inherited ones
      # included, between the ports of the children as this model has them.
      # Kept (frozen) until a declaration changes (a connection or a child
      # declared anywhere): generation asks for them once per composition.
      def port_connections
        cached(:port_connections) do
          inherited = superclass.respond_to?(:port_connections) ? superclass.port_connections : []
          (inherited + (@connections || [])).map do |c|
            from = current_port(c.from)
            to = current_port(c.to)
            from.equal?(c.from) && to.equal?(c.to) ? c : Connection.new(from, to, c.policy, c.location)
          end.freeze
        end
      end

      # Syskit's view of the connections: by pair of child names, the
      # connected port names and their policy,
      # +{ %w[source sink] => { %w[out in] => {} } }+.
      def connections
        port_connections.each_with_object({}) do |c, result|
          (result[[c.from.child_name, c.to.child_name]] ||= {})[[c.from.key.last, c.to.key.last]] = c.policy
        end
      end

      # Yields each pair of child names and their connections (see #connections).
      def each_explicit_connection(&block)
        return enum_for(__method__) unless block

        connections.each(&block)
      end

      # Whether two children's ports are connected in this composition.
      def connected?(port, other)
        port_connections.any? do |c|
          (c.from.same_port?(port) && c.to.same_port?(other)) || (c.from.same_port?(other) && c.to.same_port?(port))
        end
      end

      private

      # +port+, of the child of its name in this model: a parent's
      # declarations follow what a submodel overloads the child with, the
      # port names mapped through the services it provides.
      def current_port(port)
        child = find_child(port.child_name)
        child ? port.promote(child) : port
      end

      # +where_port+ on the model, and on its tasks: the composition's own
      # port, whose to_actual_port is the child's it is exported from.
      def define_port_reader(name)
        reader = "#{name}_port"
        define_singleton_method(reader) { find_port(name) } unless singleton_class.method_defined?(reader)
        define_method(reader) { Syskit::Port.new(model.find_port(name), self) } unless method_defined?(reader)
      end

      # Ports of a child of a child composition are that composition's to
      # connect (the connection would change its model).
      def check_grandchild_port(port, location)
        return unless port.child.reached_through

        raise DeclarationError.new(
          "#{port} is a port of a child of the child composition #{port.child.outermost_child}: " \
          'it cannot be connected from here',
          location: location, hint: "export it from #{port.composition_model} and connect the exported port"
        )
      end

      def check_connection(from, to, location)
        unless to.is_a?(ChildPort)
          raise DeclarationError.new("connect_to expects a port of another child, got #{Arguments.shown(to)}",
                                     location: location, hint: 'write a_child.out_port.connect_to b_child.in_port')
        end
        unless from.output? && to.input?
          raise DeclarationError.new("cannot connect #{from} (#{from.direction}) to #{to} (#{to.direction})",
                                     location: location, hint: 'connect an output port to an input port')
        end
        unless child_port?(to)
          raise DeclarationError.new("#{to} is not a port of a child of #{self}",
                                     location: location, hint: 'connect ports of the children of one composition')
        end
        return if from.type == to.type

        raise DeclarationError.new("cannot connect #{from} (#{from.type_description}) to #{to} " \
                                   "(#{to.type_description}): types differ",
                                   location: location, hint: 'connect ports of the same type')
      end
    end
  end
end
