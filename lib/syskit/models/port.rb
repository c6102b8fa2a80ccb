# frozen_string_literal: true

require 'forwardable'

module Syskit
  module Models
    # A port of a component model or of a data service model (Syskit's
    # +task_m.out_port+, +srv_m.find_input_port('cmd')+): the oroGen port
    # (+orogen_model+) as seen from that model (+component_model+). The
    # port of a task instance is a Syskit::Port.
    class Port
      extend Forwardable

      attr_reader :component_model, :name, :type

      # +orogen_model+: an Orogen::Port; +name+, when the port is known by
      # another name on +component_model+.
      def initialize(component_model, orogen_model, name = orogen_model.name)
        @component_model = component_model
        @port = orogen_model.is_a?(PortModifiers) ? orogen_model.orogen_port : orogen_model
        @name = name
        @type = orogen_model.type
      end

      # The port's model for +component_model+, of the class of its
      # direction (InputPort or OutputPort).
      def self.for(component_model, orogen_port)
        (orogen_port.input? ? InputPort : OutputPort).new(component_model, orogen_port)
      end

      # oroGen's port, with its modifiers (+multiplexes+,
      # +needs_reliable_connection+, +triggered_once_per_update+...).
      def orogen_model
        PortModifiers.new(@port)
      end

      # What the declaration says (see Orogen::Port and ConnectionNeeds).
      def_delegators :@port, :direction, :input?, :output?, :multiplexes?, :reliable?, :reliable, :buffer_size,
                     :static?, :orocos_type_name, :type_name, :dynamic?, :declared_type, :type_description,
                     :declared_at

      # oroGen's modifiers, said on the port itself, as in Syskit
      # (+find_output_port('samples').triggered_once_per_update+).
      READERS = (ConnectionNeeds::NEEDS - %i[multiplexes]).freeze
      def_delegators :orogen_model, *(PortModifiers.public_instance_methods(false) - READERS - %i[name type ==])

      # +port.period+ reads what the declaration says, +port.period(0.1)+
      # says it (the same for doc, burst and sample_size).
      READERS.each do |reader|
        define_method(reader) do |*args|
          args.empty? ? @port.public_send(reader) : orogen_model.public_send(reader, *args)
        end
      end

      # The same port, on +model+ (a submodel, a specialization).
      def attach(model)
        copy = dup
        copy.instance_variable_set(:@component_model, model)
        copy
      end

      # The port of a component model this port stands for (itself on a
      # component model); a data service's port has none: ArgumentError.
      def to_component_port
        if component_model.respond_to?(:self_port_to_component_port)
          return component_model.self_port_to_component_port(self)
        end

        raise ArgumentError, "cannot resolve a port of #{component_model} into a component port"
      end

      # This port on +component+, a task of its component model (for a
      # composition, the port of the child task it exports).
      def bind(component)
        component.find_port(name) || raise(ArgumentError, "#{component} has no port '#{name}'")
      end

      # #to_component_port, or itself when there is none.
      def try_to_component_port
        return self unless component_model.respond_to?(:self_port_to_component_port)

        component_model.self_port_to_component_port(self)
      end

      # Whether a connection of its component model links this port to
      # +sink+: never for the ports of task and service models, whose
      # connections are kept by compositions (see ChildPort#connected_to?).
      def connected_to?(sink)
        source = try_to_component_port
        return source.connected_to?(sink) unless source.equal?(self)

        sink = sink.try_to_component_port if sink.respond_to?(:try_to_component_port)
        !!(component_model.respond_to?(:connected?) && component_model.connected?(self, sink))
      end

      # Whether this output port can feed +sink+, an input port of the
      # same type, once both are resolved to component ports.
      def can_connect_to?(sink)
        source = try_to_component_port
        return source.can_connect_to?(sink) unless source.equal?(self) || source == self

        sink = sink.try_to_component_port if sink.respond_to?(:try_to_component_port)
        output? && sink.input? && type == sink.type
      end

      # Checks that this port may be connected to +sink+ (a port of
      # another component model): an output to an input of the same type.
      # Models are connected as children of a composition (+out_child.x_port
      # .connect_to in_child.y_port+), which is where the connection is kept.
      def connect_to(sink, _policy = {})
        location = Location.of_caller
        source = to_component_port
        sink = sink.to_component_port if sink.respond_to?(:to_component_port)
        check_connection(source, sink, location)
        raise DeclarationError.new(
          "#{source} and #{sink} are ports of task models, not of composition children: there is nothing to keep " \
          'the connection in', location: location, hint: 'connect the ports of children in a composition'
        )
      end

      # The same port of the same model: a Port, or a composition child's
      # port (ChildPort) that is this port of that child.
      def ==(other)
        (other.is_a?(Port) || other.is_a?(ChildPort)) && other.component_model == component_model &&
          other.name == name && other.orogen_port.equal?(orogen_port)
      end
      alias eql? ==

      def hash
        [Port, component_model, name].hash
      end

      def to_s
        "#{component_model}.#{name}_port[#{type.name}]"
      end
      alias short_name to_s
      alias inspect to_s

      # The Orogen::Port itself (#orogen_model is a view of it).
      def orogen_port
        @port
      end

      private

      def check_connection(source, sink, location)
        same = sink.respond_to?(:component_model) && source.component_model == sink.component_model
        PortConnectionCheck.check!(source, sink, location, same_owner: same, owner: 'component model')
      end
    end

    # An input port of a component or data service model.
    class InputPort < Port; end

    # An output port of a component or data service model.
    class OutputPort < Port; end
  end
end
