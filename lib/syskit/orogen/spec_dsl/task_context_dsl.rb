# frozen_string_literal: true

module Syskit
  module Orogen
    # Statements of a +task_context "Task" do ... end+ block.
    class TaskContextDSL
      include StatementsDSL

      def initialize(loader, spec)
        @loader = loader
        @spec = spec
      end

      def dsl_context
        "task_context '#{@spec.name.split('::', 2).last}'"
      end

      def doc(text)
        @spec.doc = text
      end

      def subclasses(parent)
        @loader.subclass(@spec, parent.to_s, Location.of_caller)
      end

      def abstract
        @spec.abstract = true
      end

      def needs_configuration
        @spec.needs_configuration = true
      end

      def property(property_name, type, default = nil)
        property = declare(@spec.properties, property_name, 'property') do |n|
          Property.new(n, @loader.resolve_type(type, Location.of_caller), default)
        end
        PropertyModifiers.new(property)
      end

      def attribute(attribute_name, type, default = nil)
        attribute = declare(@spec.attributes, attribute_name, 'attribute') do |n|
          Property.new(n, @loader.resolve_type(type, Location.of_caller), default)
        end
        PropertyModifiers.new(attribute)
      end

      def input_port(port_name, type, **_options)
        add_port(port_name, :input, type)
      end

      def output_port(port_name, type, **_options)
        add_port(port_name, :output, type)
      end

      def dynamic_input_port(pattern, type)
        add_dynamic_port(pattern, :input, type)
      end

      def dynamic_output_port(pattern, type)
        add_dynamic_port(pattern, :output, type)
      end

      def operation(operation_name)
        declare(@spec.operations, operation_name, 'operation') { |n| Operation.new(n) }
      end

      def worstcase_processing_time(seconds)
        @spec.worstcase_processing_time = seconds
      end

      %i[exception_states error_states runtime_states fatal_states states].each do |kind|
        define_method(kind) { |*names| @spec.states[kind].concat(names.map(&:to_s)) }
      end

      %i[port_driven fd_driven periodic default_activity required_activity].each do |kind|
        define_method(kind) { |*args| @spec.activity = [kind, *args] }
      end

      # Code-generation statements: accepted, meaningless for planning.
      %i[implements reports extended_state_support needs_global_initializer hidden_operations
         reconfigurable keep_last_written_value transformer stream_aligner dynamic_property
         default_policy].each do |statement|
        define_method(statement) { |*_args, **_options, &_block| nil }
      end

      private

      def declare(table, raw_name, what)
        declared_name = raw_name.to_s
        unless declared_name.match?(/\A[A-Za-z_]\w*\z/)
          raise SpecError.new("'#{declared_name}' is not a valid #{what} name",
                              location: Location.of_caller,
                              hint: 'oroGen names are C++ identifiers: letters, digits and _')
        end
        if table.key?(declared_name)
          raise SpecError.new("#{@spec.name} declares the #{what} '#{declared_name}' twice",
                              location: Location.of_caller, hint: 'remove one of the declarations')
        end

        table[declared_name] = yield(declared_name)
      end

      def add_port(port_name, direction, type)
        if @spec.find_port(port_name) && !@spec.ports.key?(port_name.to_s)
          raise SpecError.new("#{@spec.name} redeclares the port '#{port_name}' of its parent",
                              location: Location.of_caller, hint: 'give the port another name')
        end

        port = declare(@spec.ports, port_name, 'port') do |n|
          Port.new(n, direction, @loader.resolve_type(type, Location.of_caller))
        end
        PortModifiers.new(port)
      end

      def add_dynamic_port(pattern, direction, type)
        pattern = Regexp.new(pattern.to_s) unless pattern.is_a?(Regexp)
        port = DynamicPort.new(pattern, direction, @loader.resolve_type(type, Location.of_caller))
        @spec.dynamic_ports << port
        PortModifiers.new(port)
      end
    end
  end
end
