# frozen_string_literal: true

module Syskit
  module Orogen
    # A task model's .orogen declaration as extension files reach it through
    # +orogen_model+ (Syskit's name): its name, ports and properties, and
    # port modifiers as in the .orogen file.
    class ModelView
      # +declarations+: the model made in Ruby the spec is of, whose ports
      # may be declared through the view (see #input_port).
      # +model+: the task model whose oroGen model this is, if any.
      def initialize(spec, model: nil, declarations: nil, superclass: nil)
        @spec = spec
        @model = model
        @declarations = declarations
        @superclass = superclass
      end

      # An oroGen model made in Ruby, of no task model yet, as Syskit's
      # tests make them (+Models.create_orogen_task_context_model+,
      # +OroGen::Spec::TaskContext.new(project, 'lib::Task')+): a spec
      # called +name+, of the +project+, deriving from +subclasses+ (another
      # such view). Its task model is made by TaskContext.define_from_orogen.
      def self.define(name = nil, project: nil, subclasses: nil)
        new(TaskSpec.new(name, project, superclass: subclasses&.spec), superclass: subclasses)
      end

      # The spec it is a view of (Orogen::TaskSpec).
      attr_reader :spec

      # The task model it is the oroGen model of (set once it is made).
      attr_writer :model

      # The project (task library) the model is of, as given.
      def project
        @spec.library
      end

      # The task's states, as an .orogen file declares them
      # (+error_states :BLOCKED+), each with its event (see
      # Models::TaskContext#state_events).
      %i[exception_states error_states runtime_states fatal_states].each do |kind|
        define_method(kind) do |*names|
          @spec.states[kind].concat(names.map(&:to_s))
          @model&.define_event_readers
        end
      end

      # Declares a port on a task model made in Ruby, as Syskit's tests do
      # through its oroGen model; those of an .orogen file are declared there.
      def input_port(name, type)
        declarations('input_port').input_port(name, type)
      end

      def output_port(name, type)
        declarations('output_port').output_port(name, type)
      end

      # Declares a pattern of ports created at configure time (see
      # RubyTaskContext::Declarations#dynamic_input_port).
      def dynamic_input_port(pattern, type = nil)
        declarations('dynamic_input_port').dynamic_input_port(pattern, type)
      end

      def dynamic_output_port(pattern, type = nil)
        declarations('dynamic_output_port').dynamic_output_port(pattern, type)
      end

      # The patterns of ports created at configure time (Syskit::DynamicPort).
      def dynamic_ports
        @spec.all_dynamic_ports
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

      # The input port called +name+ (with its modifiers), nil when there
      # is none or it is an output.
      def find_input_port(name)
        find_port_of(:input, name)
      end

      # The output port called +name+, nil when there is none or it is an
      # input.
      def find_output_port(name)
        find_port_of(:output, name)
      end

      def has_port?(name) # rubocop:disable Naming/PredicatePrefix -- oroGen's name
        !@spec.find_port(name).nil?
      end

      # The oroGen model this one derives from (that of the parent task
      # model when it stands for it), nil for a root.
      def superclass
        return @superclass if @superclass

        parent = @spec.superclass
        return unless parent

        parent_model = @model&.superclass
        if parent_model.respond_to?(:spec) && parent_model.spec.equal?(parent)
          parent_model.orogen_model
        else
          ModelView.new(parent)
        end
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

      # Views of the same spec are the same oroGen model.
      def ==(other)
        other.is_a?(ModelView) && other.spec.equal?(spec)
      end
      alias eql? ==

      def hash
        spec.hash
      end

      private

      def find_port_of(direction, name)
        port = @spec.find_port(name)
        PortModifiers.new(port) if port&.direction == direction
      end

      def declarations(statement)
        return @declarations if @declarations

        raise DeclarationError.new(
          "#{statement} on the oroGen model of #{name}: its ports are declared in its .orogen file",
          location: Location.of_caller, hint: 'declare it there, or in a submodel made in Ruby (Model.new_submodel)'
        )
      end
    end
  end
end
