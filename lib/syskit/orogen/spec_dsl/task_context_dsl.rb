# frozen_string_literal: true

module Syskit
  module Orogen
    # Statements of a +task_context "Task" do ... end+ block.
    class TaskContextDSL
      include StatementsDSL

      # A correct call of each statement, for the hints of argument errors.
      EXAMPLES = {
        'property' => "property 'rate', 'int', 100", 'attribute' => "attribute 'rate', 'int', 100",
        'input_port' => "input_port 'command', '/base/samples/RigidBodyState'",
        'output_port' => "output_port 'pose_samples', '/base/samples/RigidBodyState'",
        'dynamic_input_port' => "dynamic_input_port(/^w\\w+$/, '/canbus/Message')",
        'dynamic_output_port' => "dynamic_output_port(/^\\w+$/, '/canbus/Message')",
        'operation' => "operation('reset')"
      }.freeze

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

      def property(property_name = nil, type = nil, default = nil)
        PropertyModifiers.new(add_property(@spec.properties, 'property', property_name, type, default))
      end

      def attribute(attribute_name = nil, type = nil, default = nil)
        PropertyModifiers.new(add_property(@spec.attributes, 'attribute', attribute_name, type, default))
      end

      def input_port(port_name = nil, type = nil, **_options)
        add_port(port_name, :input, type)
      end

      def output_port(port_name = nil, type = nil, **_options)
        add_port(port_name, :output, type)
      end

      def dynamic_input_port(pattern = nil, type = nil)
        add_dynamic_port(pattern, :input, type)
      end

      def dynamic_output_port(pattern = nil, type = nil)
        add_dynamic_port(pattern, :output, type)
      end

      def operation(operation_name = nil)
        declare(@spec.operations, operation_name, 'operation') { |n| Operation.new(n) }
      end

      def worstcase_processing_time(seconds)
        @spec.worstcase_processing_time = seconds
      end

      %i[exception_states error_states runtime_states fatal_states states].each do |kind|
        define_method(kind) { |*names| @spec.states[kind].concat(names.map(&:to_s)) }
      end

      # oroGen's other name for runtime_states.
      def reports(*names)
        runtime_states(*names)
      end

      %i[port_driven fd_driven periodic default_activity required_activity].each do |kind|
        define_method(kind) do |*args|
          @spec.activity = [kind, *args]
          ActivityModifiers.new
        end
      end

      # A property declared before (or inherited), to change it:
      # +find_property('timeout').dynamic+.
      def find_property(property_name)
        found = @spec.all_properties[property_name.to_s] || @spec.properties[property_name.to_s]
        unless found
          raise SpecError.new("#{@spec.name} has no property '#{property_name}'",
                              location: Location.of_caller, hint: 'declare it with property before this line')
        end

        PropertyModifiers.new(found)
      end

      # Code-generation statements: accepted, meaningless for planning.
      %i[implements extended_state_support needs_global_initializer hidden_operations
         reconfigurable keep_last_written_value dynamic_property default_policy].each do |statement|
        define_method(statement) { |*_args, **_options, &_block| nil }
      end

      # A port type wrapped by an oroGen plugin (+spatio_temporal(T)+ of
      # envire's plugin, the type with a time and a frame): not modelled,
      # with a warning; the port has the inner type.
      def spatio_temporal(type)
        Syskit.app&.not_modelled("spatio_temporal (envire's oroGen plugin) in #{dsl_context}", Location.of_caller)
        type
      end

      # oroGen's transformer plugin: frames, transformations and aligned
      # ports, and the properties and ports the plugin adds to the task
      # (see TransformerDSL). Repeated blocks add to the first.
      def transformer(&)
        TransformerDSL.new(self, @spec, @spec.own_transformer).evaluate(Location.of_caller, &)
      end

      # oroGen's stream aligner plugin (see StreamAlignerDSL).
      def stream_aligner(&)
        StreamAlignerDSL.new(self, @spec, @spec.own_stream_aligner).evaluate(Location.of_caller, &)
      end

      # A property an oroGen plugin adds, unless the task (or its parent)
      # has it already: the plugin's blocks may be repeated or inherited.
      def plugin_property(name, type, default)
        return if @spec.all_properties.key?(name) || @spec.properties.key?(name)

        import_plugin_types(type)
        add_property(@spec.properties, 'property', name, type, default)
      end

      def plugin_output_port(name, type, typekit:)
        plugin_port(name, :output, type, typekit)
      end

      def plugin_input_port(name, type)
        plugin_port(name, :input, type, 'base')
      end

      private

      def plugin_port(name, direction, type, typekit)
        return if @spec.find_port(name)

        @loader.import_types(typekit, Location.of_caller)
        add_port(name, direction, type)
      end

      def import_plugin_types(type)
        @loader.import_types('base', Location.of_caller) if type.include?('/base/')
      end

      # +statement+: the DSL word, when it is not +what+ (input_port for a port).
      def declare(table, raw_name, what, statement = what, pattern: Arguments::IDENTIFIER)
        kind = pattern == Arguments::IDENTIFIER ? 'a C++ identifier' : 'letters, digits and _'
        declared_name = Arguments.name(raw_name, statement: statement, what: "a #{what} name (#{kind})",
                                                 example: EXAMPLES.fetch(statement), pattern: pattern,
                                                 error_class: SpecError)
        if table.key?(declared_name)
          raise SpecError.new("#{@spec.name} declares the #{what} '#{declared_name}' twice",
                              location: Location.of_caller, hint: 'remove one of the declarations')
        end

        table[declared_name] = yield(declared_name)
      end

      # A property or attribute; its default, when given, must be a value of
      # its type (checked here, at its line, not when a plan shows it).
      def add_property(table, what, raw_name, type, default)
        location = Location.of_caller
        declare(table, raw_name, what) do |name|
          resolved = @loader.resolve_type(argument_type(type, what, name), location)
          check_default(what, name, resolved, default, location) unless default.nil?
          Property.new(name, resolved, default)
        end
      end

      def argument_type(type, what, name)
        Arguments.given(type, statement: "#{what} '#{name}'", what: 'a type', error_class: SpecError,
                              example: EXAMPLES.fetch(what).sub(/'\w+'/, "'#{name}'"))
      end

      def check_default(what, name, type, default, location)
        type.from_ruby(default)
      rescue Types::ValueError => e
        zero = type.to_plain(type.zero)
        example = ", e.g. #{zero.inspect}" if [Numeric, String, TrueClass, FalseClass].any? { |k| zero.is_a?(k) }
        raise SpecError.new("the default value of #{what} '#{name}' does not fit its type: #{e.message}",
                            location: location, hint: "give a default of type #{type}#{example}, or none")
      end

      def add_port(port_name, direction, type)
        if @spec.find_port(port_name) && !@spec.ports.key?(port_name.to_s)
          raise SpecError.new("#{@spec.name} redeclares the port '#{port_name}' of its parent",
                              location: Location.of_caller, hint: 'give the port another name')
        end

        what = "#{direction}_port"
        port = declare(@spec.ports, port_name, 'port', what, pattern: Arguments::PORT_NAME) do |n|
          location = Location.of_caller
          Port.new(n, direction, @loader.resolve_type(argument_type(type, what, n), location),
                   declared_type: type, location: location)
        end
        PortModifiers.new(port)
      end

      def add_dynamic_port(pattern, direction, type)
        what = "dynamic_#{direction}_port"
        pattern = dynamic_port_pattern(pattern, what)
        # Without a type, oroGen creates ports of any type (a logger's inputs).
        type &&= @loader.resolve_type(type, Location.of_caller)
        port = DynamicPort.new(pattern, direction, type)
        @spec.dynamic_ports << port
        PortModifiers.new(port)
      end

      # A dynamic port's name pattern: a Regexp, or a String read as one.
      def dynamic_port_pattern(pattern, what)
        Arguments.given(pattern, statement: what, what: 'a name pattern', error_class: SpecError,
                                 example: EXAMPLES.fetch(what))
        return pattern if pattern.is_a?(Regexp)

        Regexp.new(pattern.to_s)
      rescue RegexpError => e
        raise SpecError.new("#{what}: #{pattern.inspect} is not a regular expression (#{e.message})",
                            location: Location.of_caller, hint: "write #{EXAMPLES.fetch(what)}")
      end
    end
  end
end
