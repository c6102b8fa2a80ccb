# frozen_string_literal: true

module Syskit
  module Orogen
    # What an .orogen file says of one task context: its ports, dynamic port
    # patterns, properties, operations, states and activity.
    class TaskSpec
      attr_reader :name, :library, :properties, :attributes, :ports,
                  :dynamic_ports, :operations, :states, :declared_at
      attr_accessor :superclass, :doc, :abstract, :needs_configuration, :activity, :worstcase_processing_time

      def initialize(name, library, superclass: nil, location: nil)
        @name = name
        @library = library
        @superclass = superclass
        @declared_at = location
        @properties = {}
        @attributes = {}
        @ports = {}
        @dynamic_ports = []
        @operations = {}
        @states = Hash.new { |h, k| h[k] = [] }
        @abstract = false
        @needs_configuration = false
      end

      def abstract?
        abstract
      end

      # Ports, including those inherited from the parent task, by name.
      def all_ports
        @all_ports || (superclass ? superclass.all_ports : {}).merge(ports)
      end

      # Adds +port+ (made from a dynamic port pattern, see
      # Models::DynamicServices) to a spec that may already be finalized.
      def add_port(port)
        ports[port.name] = port
        @all_ports &&= (superclass ? superclass.all_ports : {}).merge(ports).freeze
      end

      def all_dynamic_ports
        @all_dynamic_ports || ((superclass ? superclass.all_dynamic_ports : []) + dynamic_ports)
      end

      def all_properties
        @all_properties || (superclass ? superclass.all_properties : {}).merge(properties)
      end

      # Operations, including those inherited from the parent task, by name.
      def all_operations
        @all_operations || (superclass ? superclass.all_operations : {}).merge(operations)
      end

      # What its transformer and stream_aligner blocks declare (see
      # StreamAlignerSpec), or what it inherits; nil without any.
      def transformer
        @own_transformer || superclass&.transformer
      end

      def stream_aligner
        @own_stream_aligner || superclass&.stream_aligner
      end

      # The transformer its own block declares, which extends the
      # inherited one: made by the first block.
      def own_transformer
        @own_transformer ||= TransformerSpec.new(superclass&.transformer)
      end

      def own_stream_aligner
        @own_stream_aligner ||= StreamAlignerSpec.new
      end

      def find_port(name)
        all_ports[name.to_s]
      end

      # The name of the port in which a task with oroGen's extended state
      # support writes its state.
      STATE_PORT = 'state'

      # oroGen's +extended_state_support+, which oroGen applies to every
      # task context of a project and Syskit to every task model made in
      # Ruby: the task writes its state in a +state+ output port of
      # +type+ (an int32), unless it has one already.
      def extended_state_support(type)
        return if find_port(STATE_PORT)

        ports[STATE_PORT] = Port.new(STATE_PORT, :output, type)
      end

      # Whether +port+ is the state port of extended state support.
      def self.state_port?(port)
        port.name == STATE_PORT && port.direction == :output && port.type.name == '/int32_t'
      end

      # The dynamic port pattern +name+ of +type+ would be created from.
      def dynamic_port_for(direction, name, type)
        # Array#index, not #find or a return from #each: asked per device,
        # it allocates nothing.
        patterns = all_dynamic_ports
        found = patterns.index { |p| p.direction == direction && p.match?(name, type) }
        patterns[found] if found
      end

      # Called once the task_context block is evaluated: the inherited views
      # are computed once, generation reads them often.
      def finalize
        @all_ports = all_ports.freeze
        @all_dynamic_ports = all_dynamic_ports.freeze
        @all_properties = all_properties.freeze
        @all_operations = all_operations.freeze
      end

      def to_s
        name
      end
    end
  end
end
