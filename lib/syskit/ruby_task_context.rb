# frozen_string_literal: true

module Syskit
  # A component written in Ruby (Syskit::RubyTaskContext): a task context
  # whose ports and properties are declared in its class body rather than
  # in an .orogen file.
  #
  #   class Generator < Syskit::RubyTaskContext
  #     output_port 'out', '/double'
  #     property 'period', '/double', 0.1
  #   end
  #
  # It is deployed with +Syskit.conf.use_ruby_tasks Generator => 'name'+,
  # and is otherwise planned as any task context. What it does at runtime
  # (its events, its threads) is Roby's, and not modelled.
  class RubyTaskContext < TaskContext
    # The spec of a Ruby task model: named after the model (its constant,
    # known once the class is assigned to one), never finalized, so that
    # its ports and properties are read as declared so far.
    class Spec < Orogen::TaskSpec
      def initialize(model, superclass)
        super(nil, nil, superclass: superclass, location: model.declared_at)
        @model = model
      end

      # The name of the oroGen model, when given apart from the model's
      # (+new_submodel(orogen_model_name: 'lib::Task')+).
      attr_writer :orogen_model_name

      def name
        @orogen_model_name || @model.name
      end
    end

    # The class statements of task models declared in Ruby: ports and
    # properties in the class body, a name given to new_submodel.
    module Declarations
      # Where the model was declared.
      attr_reader :declared_at

      # The constant's name, else the one given to new_submodel.
      def name
        Module.instance_method(:name).bind_call(self) || @given_name || "anonymous ruby task (#{declared_at})"
      end

      def input_port(name, type)
        add_port(name, :input, type)
      end

      def output_port(name, type)
        add_port(name, :output, type)
      end

      # Declares ports the task creates at configure time, by name pattern:
      # +dynamic_output_port(/^\w+$/, '/double')+ (a type of nil: any type).
      def dynamic_input_port(pattern, type = nil)
        add_dynamic_port(pattern, :input, type)
      end

      def dynamic_output_port(pattern, type = nil)
        add_dynamic_port(pattern, :output, type)
      end

      # The task's states, as an .orogen file declares them
      # (+runtime_states :moving+; +reports+ is oroGen's other name for
      # runtime_states).
      %i[exception_states error_states runtime_states fatal_states].each do |kind|
        define_method(kind) do |*names|
          spec.states[kind].concat(names.map(&:to_s))
          define_event_readers
        end
      end

      def reports(*names)
        runtime_states(*names)
      end

      # What Syskit calls the oroGen model of a task model made in Ruby:
      # ports may be declared through it too
      # (+model.orogen_model.input_port 'in', '/double'+).
      def orogen_model
        @orogen_model ||= Orogen::ModelView.new(spec, model: self, declarations: self)
      end

      # Declares a property: +property 'period', '/double', 0.1+.
      def property(name, type, default = nil)
        name = check_name(name, 'property')
        property = Orogen::Property.new(name, Models.resolve_type(type, Location.of_caller), default)
        spec.properties[name] = property
        @properties_class = nil
        define_property_reader(name)
        Orogen::PropertyModifiers.new(property)
      end

      # Sets up +submodel+, a subclass of a model declared in Ruby or of
      # an oroGen task model, as a model declared in Ruby.
      def declared_in_ruby(submodel, location)
        submodel.extend(Declarations)
        submodel.instance_variable_set(:@declared_at, location)
        spec = Spec.new(submodel, submodel.superclass.spec)
        extended_state_support(spec)
        submodel.send(:setup_model, spec)
        Models.register_model(submodel)
        submodel
      end

      # Syskit gives every task model made in Ruby oroGen's extended state
      # support (a +state+ port, see Orogen::TaskSpec), when an app is
      # there to resolve its type.
      def extended_state_support(spec)
        app = Syskit.app
        spec.extended_state_support(app.types.resolve('/int32_t')) if app
      end

      private

      # Its submodels are declared in Ruby through #inherited (see
      # Models::Component#new_submodel).
      def submodel_class
        Class.new(self)
      end

      def inherited(submodel)
        super
        declared_in_ruby(submodel, Location.of_caller)
      end

      def add_port(name, direction, type)
        name = check_name(name, "#{direction}_port")
        location = Location.of_caller
        port = Orogen::Port.new(name, direction, Models.resolve_type(type, location), location: location)
        spec.ports[name] = port
        Models::Component.declarations_changed
        define_port_reader(name)
        PortModifiers.new(port)
      end

      def add_dynamic_port(pattern, direction, type)
        pattern = Regexp.new(pattern.to_s) unless pattern.is_a?(Regexp)
        type &&= Models.resolve_type(type, Location.of_caller)
        port = DynamicPort.new(pattern, direction, type)
        spec.dynamic_ports << port
        Models::Component.declarations_changed
        PortModifiers.new(port)
      end

      def check_name(name, statement)
        name = Arguments.name(name, statement: statement, what: 'a name', pattern: Arguments::METHOD_NAME,
                                    example: "#{statement} 'out', '/double'")
        return name unless spec.find_port(name) || spec.all_properties.key?(name)

        raise DeclarationError.new("#{self.name} already has a port or property named '#{name}'",
                                   location: Location.of_caller, hint: 'give it another name')
      end
    end

    extend Declarations

    setup_model(Spec.new(self, nil))
  end
end
