# frozen_string_literal: true

module Syskit
  # Models of composition children's ports (see CompositionChild).
  module Models
    # A port of a composition child (+arm_child.joints_cmd_port+): what
    # +connect_to+ and +export+ take. It knows the model that declares it
    # (+owner+: the child's task model, or one of its service models), so
    # that it maps onto whatever component fills the child.
    class ChildPort
      attr_reader :child, :name, :direction, :type, :owner

      # Connection policy keys Syskit accepts (Orocos's), and the kinds of
      # connections.
      POLICY_KEYS = %i[type size init pull lock lock_policy transport data_size name_id].freeze
      POLICY_TYPES = %i[data buffer circular_buffer].freeze

      # +port+: the port of +owner+ (a Port).
      def initialize(child, port, owner)
        @port = port
        @child = child
        @name = port.name
        @direction = port.direction
        @type = port.type
        @owner = owner
      end

      # The same port, of +child+: the child of the same name as a
      # submodel (or an overload) sees it, whose models the port then maps
      # onto.
      def promote(child)
        child.equal?(@child) ? self : ChildPort.new(child, @port, owner)
      end

      # The port's name in the model that declares it.
      def owner_port
        name
      end

      # This port on +task+, the task standing for the child: the task's
      # port the owner's port maps to.
      def bind(task)
        raise ArgumentError, "#{task} is no #{owner}: it cannot stand for #{child}" unless task.model.fullfills?(owner)

        port_name = Models.mapped_port_name(task.model, owner, owner_port) || name
        task.find_port(port_name) || raise(ArgumentError, "#{task} has no port '#{port_name}' for #{self}")
      end

      # The oroGen port it is (what an export of it keeps, see
      # CompositionPorts#ports).
      def orogen_model
        @port.is_a?(Port) ? @port.orogen_model : @port
      end

      # The oroGen port of the owner's port (see Port#orogen_port).
      def orogen_port
        @port.is_a?(Port) ? @port.orogen_port : @port
      end

      # The typedef name the port was declared with, if any, and the type
      # as declared (see Orogen::Port#type_description).
      def declared_type
        @port.declared_type if @port.respond_to?(:declared_type)
      end

      def type_description
        @port.respond_to?(:type_description) ? @port.type_description : type.name
      end

      # Where the owner's port was declared (see Orogen::Port#declared_at).
      def declared_at
        orogen_port.declared_at if orogen_port.respond_to?(:declared_at)
      end

      def input?
        direction == :input
      end

      def output?
        direction == :output
      end

      # Whether the port accepts several writers (oroGen's +multiplexes+).
      def multiplexes?
        @port.multiplexes?
      end

      def child_name
        child.child_name
      end

      # The composition model the port's child belongs to.
      def composition_model
        child.composition_model
      end

      # Syskit's +port.component_model+: the child.
      def component_model
        child
      end

      def to_component_port
        self
      end

      # Connects this output port to the input port +other+ (or to the only
      # input port of +other+'s type when +other+ is a child), with an
      # optional policy: +connect_to other, type: :buffer, size: 10+.
      def connect_to(other, policy = {})
        location = Location.of_caller
        return ChildPort.autoconnect([self], other, policy, location) if other.is_a?(ChildConnections)

        composition_model.add_connection(self, other, ChildPort.policy(policy, location), location)
        self
      end

      # Whether this port and +other+ are connected in the composition.
      def connected_to?(other)
        composition_model.connected?(self, other)
      end

      # The same port seen from the most specific model the child requires
      # (a port of a service is the port its provider maps it to): two
      # child ports are the same port when their keys are equal.
      def key
        @key ||= begin
          model = child.models.find { |m| !m.equal?(owner) && m.fullfills?(owner) }
          name = model ? Models.mapped_port_name(model, owner, owner_port) : owner_port
          [child_name, name || owner_port]
        end
      end

      def same_port?(other)
        other.respond_to?(:key) && key == other.key
      end

      # The same port of the same child (see #key); a Port of the child
      # (+Port.new(child, srv_port.orogen_model)+, as Syskit's tests make
      # them) is equal too (see Port#==).
      def ==(other)
        return other == self if other.is_a?(Port)

        other.is_a?(ChildPort) && same_port?(other)
      end
      alias eql? ==

      def hash
        key.hash
      end

      def to_s
        "#{child}.#{name}_port"
      end
      alias inspect to_s

      # A policy as given (+type: :buffer, size: 10+), checked: a model keeps
      # it as Syskit does; the plan writes it as data (Network::Policy.of).
      def self.policy(options, location)
        options = options.transform_keys(&:to_sym)
        unknown = options.keys - POLICY_KEYS
        unless unknown.empty?
          raise DeclarationError.new("unknown connection policy option #{unknown.map { |k| "#{k}:" }.join(', ')}",
                                     location: location,
                                     hint: 'policies are written type: :buffer, size: 10 (or type: :data)')
        end
        type = options[:type]
        if type && !POLICY_TYPES.include?(type.to_sym)
          raise DeclarationError.new("unknown connection type #{type.inspect}",
                                     location: location, hint: "use one of #{POLICY_TYPES.map(&:inspect).join(', ')}")
        end

        options.freeze
      end

      # Connects each of +outputs+ to the input port of +other+ (a child, or
      # an input port) it resolves to (see Syskit.resolve_connections).
      def self.autoconnect(outputs, other, policy, location)
        inputs = other.is_a?(ChildPort) ? [other] : other.each_input_port.to_a
        pairs = Syskit.resolve_connections(outputs, inputs, location: location)
        if pairs.empty?
          raise DeclarationError.new(
            "#{outputs.first&.child || 'the child'} has no output port of the type of an input of #{other}",
            location: location, hint: 'connect ports explicitly: a_child.x_port.connect_to b_child.y_port'
          )
        end

        pairs.each { |out, input| out.composition_model.add_connection(out, input, policy(policy, location), location) }
      end
    end

    # What a selection may name to share a task between children: another
    # child (+first_child+, +first_child.src_child+) or a child's service
    # (+first_child.pose_srv+). The generator selects the task built for
    # +referenced_child+, through +referenced_service+ when there is one.
    module ChildReference
    end

    # +connect_to+ of what holds a child's ports: a child, or a child seen
    # through one of its services (CompositionChild::ServiceView). Each
    # output connects to the input of +other+ (a child, a view, a port)
    # of its type, as Syskit's +connect_to+ between components.
    module ChildConnections
      def connect_to(other, policy = {})
        ChildPort.autoconnect(each_output_port.to_a, other, policy, Location.of_caller)
        self
      end

      # Syskit's +connect_ports(other_child, ['out', 'in'] => policy)+:
      # connects ports of this child to ports of +other+, a child of the
      # same composition model, by name.
      def connect_ports(other, mappings)
        unless other.respond_to?(:composition_model) && other.composition_model.equal?(composition_model)
          raise ArgumentError, "#{self} can only be connected to children of #{composition_model}, " \
                               "got #{Arguments.shown(other)}"
        end

        mappings.each do |(out_name, in_name), policy|
          out = find_output_port(out_name) ||
                raise(InvalidCompositionChildPort.new(composition_model, child_name, out_name))
          input = other.find_input_port(in_name) ||
                  raise(InvalidCompositionChildPort.new(composition_model, other.child_name, in_name))
          out.connect_to(input, policy || {})
        end
        self
      end
    end

    # The name of the port of +model+ that +owner+'s port +port_name+ is
    # (through a service +model+ provides, or the same name for a
    # submodel); nil when +model+ does not fullfill +owner+.
    def self.mapped_port_name(model, owner, port_name)
      return port_name if model.equal?(owner) || (model.is_a?(Class) && owner.is_a?(Class) && model <= owner)

      if model.is_a?(DataServiceModel)
        return model.fullfills?(owner) ? model.port_mappings_for(owner)[port_name] : nil
      end

      srv = model.services_fulfilling(owner).first if model.respond_to?(:services_fulfilling)
      srv&.task_port_for(owner, port_name)&.name
    end
  end
end
