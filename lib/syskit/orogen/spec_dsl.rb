# frozen_string_literal: true

module Syskit
  module Orogen
    # Statements shared by the DSL objects of .orogen files: unknown calls are
    # explained with the statements that exist (see UserCode).
    module StatementsDSL
      def explain_missing(name)
        statements = self.class.public_instance_methods(false).map(&:to_s) - %w[dsl_context]
        ["unknown statement '#{name}' in #{dsl_context}#{Naming.did_you_mean(name, statements)}",
         "the statements known here are #{statements.sort.join(', ')}"]
      end
    end

    # Top-level statements of an .orogen file.
    class ProjectDSL
      include StatementsDSL

      # C++ class names, in namespaces or not (Task, test::Replay).
      TASK_NAME = /\A[A-Za-z_]\w*(?:::[A-Za-z_]\w*)*\z/
      # Deployments name executables: letters, digits, _ and -.
      DEPLOYMENT_NAME = /\A[A-Za-z0-9_][A-Za-z0-9_-]*\z/

      def initialize(loader)
        @loader = loader
      end

      def dsl_context
        'an .orogen file'
      end

      def name(project_name)
        @loader.check_project_name(project_name.to_s, Location.of_caller)
      end

      def task_context(task_name = nil, subclasses: nil, **_options, &block)
        task_name = Arguments.name(task_name, statement: 'task_context', what: 'a task name (a C++ class name)',
                                              example: "task_context 'Task' do ... end", pattern: TASK_NAME,
                                              rule: 'letters, digits and _, not starting with a digit, ' \
                                                    'in namespaces or not (test::Replay)',
                                              error_class: SpecError)
        @loader.define_task(task_name, subclasses&.to_s, Location.of_caller, &block)
      end

      def deployment(deployment_name = nil, &)
        deployment_name = Arguments.name(deployment_name, statement: 'deployment', what: 'a deployment name',
                                                          example: "deployment 'test_gps' do ... end",
                                                          pattern: DEPLOYMENT_NAME, error_class: SpecError)
        @loader.define_deployment(deployment_name, Location.of_caller, &)
      end

      def static_deployment(&block)
        DeploymentDSL.new(@loader, DeploymentSpec.new('static')).instance_eval(&block) if block
      end

      def import_types_from(typekit_or_header, *_args, **_options)
        @loader.import_types(typekit_or_header.to_s, Location.of_caller)
      end

      def using_task_library(library_name, **_options)
        @loader.using_task_library(library_name.to_s, Location.of_caller)
      end

      def corba_enabled?
        true
      end

      # Build-level statements: accepted, meaningless for planning.
      %i[version using_library using_typekit typekit enable_namespace max_sizes
         export_types orogen_version default_task_context_superclass].each do |statement|
        define_method(statement) { |*_args, **_options, &_block| nil }
      end
    end

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

      # +statement+: the DSL word, when it is not +what+ (input_port for a port).
      def declare(table, raw_name, what, statement = what)
        declared_name = Arguments.name(raw_name, statement: statement, what: "a #{what} name (a C++ identifier)",
                                                 example: EXAMPLES.fetch(statement), error_class: SpecError)
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
        port = declare(@spec.ports, port_name, 'port', what) do |n|
          Port.new(n, direction, @loader.resolve_type(argument_type(type, what, n), Location.of_caller))
        end
        PortModifiers.new(port)
      end

      def add_dynamic_port(pattern, direction, type)
        what = "dynamic_#{direction}_port"
        pattern = dynamic_port_pattern(pattern, what)
        type = Arguments.given(type, statement: "#{what} #{pattern.inspect}", what: 'a type', error_class: SpecError,
                                     example: EXAMPLES.fetch(what))
        port = DynamicPort.new(pattern, direction, @loader.resolve_type(type, Location.of_caller))
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

    # Statements of a +deployment "name" do ... end+ block.
    class DeploymentDSL
      include StatementsDSL

      # What +task(...)+ returns: activity settings, accepted.
      class DeployedTaskDSL
        %i[periodic realtime non_realtime priority triggered fd_driven sequential slave_of
           stacksize start port_driven].each do |setting|
          define_method(setting) { |*_args, **_options| self }
        end
      end

      def initialize(loader, deployment)
        @loader = loader
        @deployment = deployment
      end

      def dsl_context
        "deployment '#{@deployment.name}'"
      end

      def task(task_name, model_name)
        location = Location.of_caller
        model = @loader.find_task_model(model_name.to_s, location)
        @deployment.add_task(task_name.to_s, model, location: location)
        DeployedTaskDSL.new
      end

      def corba_enabled?
        true
      end

      # Runtime-only statements: accepted.
      %i[add_default_logger browse do_not_install add_peers connect toplevel].each do |statement|
        define_method(statement) { |*_args, **_options| nil }
      end
    end
  end
end
