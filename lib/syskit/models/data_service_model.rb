# frozen_string_literal: true

require 'syskit/port'
require 'syskit/models/model_hierarchy'
require 'syskit/models/port_lookup'
require 'syskit/models/provided_models'
require 'syskit/models/bus_service_role'
require 'syskit/models/service_model_binding'
require 'syskit/models/task_requirements'

module Syskit
  # The plain model objects the DSL records declarations into.
  module Models
    # A data service: a named set of ports that components provide
    # (+data_service_type 'Pose' do output_port 'pose', '/base/Pose' end+).
    # This file holds its declaration, naming and ports; what it provides
    # is in ProvidedModels, what a bus's services add in BusServiceRole,
    # how components are bound to it in ServiceModelBinding.
    #
    # Models are modules so that assigning one to a constant names it, as Ruby
    # does for any module (+Device = DeviceModel.new+ is then called Device).
    class DataServiceModel < Module
      include ModelHierarchy
      include PortLookup
      include PortModelLookups
      include ProvidedModels
      include BusServiceRole
      include ServiceModelBinding
      include TaskRequirementStatements

      attr_reader :ports, :parents, :declared_at
      attr_accessor :doc

      # The word used for this kind of model in messages.
      def self.kind
        'data service'
      end

      # Defines the model +name+ in +namespace+ (the module the statement is
      # in), provides +root+, then evaluates the declaration block on it.
      def self.define(namespace, name, location:, root:, model_class: self, **options, &block)
        name = name.to_s
        unless Naming.constant_name?(name)
          raise DeclarationError.new(
            "'#{name}' is not a valid name for a #{kind}",
            location: location,
            hint: "model names are Ruby constant names, e.g. '#{Naming.camelize(name.gsub(/\W/, '_'))}'"
          )
        end
        if namespace.const_defined?(name, false)
          existing = namespace.const_get(name, false)
          return redeclare(existing, "#{namespace}::#{name}", model_class, location, **options, &block)
        end

        model = model_class.build(location: location, name: namespace.name ? "#{namespace}::#{name}" : name)
        begin
          model.send(:declare, root, options, block)
        ensure
          # As MetaRuby does, the constant names the model once its block
          # has run: a name in the block means what it meant before. It is
          # set when the block fails too, so that what follows finds it.
          namespace.const_set(name, model) unless namespace.const_defined?(name, false)
        end
      end

      # A model declared again: the gem's bundled common models give way to
      # a real bundle's or the app's declaration, and a model of the same
      # kind is reopened, as Rock's bundles expect (Syskit lets the second
      # declaration replace the first; reopening keeps what referred to the
      # first one valid), with a warning. Anything else is an error.
      def self.redeclare(existing, full_name, model_class, location, ...)
        where = existing.respond_to?(:declared_at) && existing.declared_at ? " at #{existing.declared_at}" : ''
        unless existing.instance_of?(model_class)
          raise DeclarationError.new("#{full_name} is already defined#{where}",
                                     location: location, hint: 'give the new model another name')
        end

        unless existing.bundled?
          Syskit.app&.problems&.push(Warning.new(
            "#{full_name} is declared again (first#{where}): both declarations apply",
            location: location, hint: 'remove one of them, or give one another name'
          ))
        end
        existing.reopen(location, ...)
      end

      def initialize(location: nil, name: nil)
        super()
        @declared_at = location || Location.of_caller
        @given_name = name
        @ports = {}
        @parents = {}
        @timing = {}
      end

      # Where the model was declared, as Syskit's [[file, line]] list.
      def definition_location
        declared_at ? [[declared_at.path, declared_at.lineno]] : []
      end

      # Whether the gem's bundled common models declare this model.
      def bundled?
        declared_at&.path.to_s.start_with?("#{App::BUNDLED_MODELS}/")
      end

      # Evaluates another declaration of this bundled model on it: the
      # model is then the user's (errors point at their declaration).
      def reopen(location, **options, &block)
        @declared_at = location
        apply_options(**options)
        instance_eval(&block) if block
        finalize_declaration
        self
      end

      # Options of the declaration statement, applied once the model is named.
      def apply_options(**options)
        return if options.empty?

        raise DeclarationError.new("unknown option(s) #{options.keys.join(', ')} for #{kind} #{self}",
                                   location: declared_at)
      end

      # Checks run once the declaration block has been evaluated.
      def finalize_declaration; end

      # A Queries::DataServiceMatcher finding the services of this model on
      # the tasks that provide it.
      def match
        Queries::DataServiceMatcher.new(Queries::ComponentMatcher.new.with_model(self)).with_model(self)
      end

      # The constant name, or the name given at creation for anonymous models.
      def name
        constant_name = super
        constant_name && !constant_name.start_with?('#<') ? constant_name : @given_name
      end

      # An anonymous model is shown with a number of its own, so that two
      # are told apart (Syskit's show their address): Syskit's tests name
      # services after anonymous models (+provides srv, as: srv.to_s+).
      def to_s
        name || (@anonymous_name ||= "anonymous #{self.class.kind} ##{DataServiceModel.next_anonymous_number}")
      end

      ANONYMOUS_LOCK = Mutex.new
      private_constant :ANONYMOUS_LOCK

      def self.next_anonymous_number
        ANONYMOUS_LOCK.synchronize { @anonymous_number = (@anonymous_number || 0) + 1 }
      end
      alias inspect to_s

      # The name shown to users: #to_s, as Syskit's models have it, so that
      # a model class that shows its models otherwise is shown so everywhere.
      def short_name
        to_s
      end

      def kind
        self.class.kind
      end

      # Declares an input port: +input_port 'cmd', '/base/Command'+.
      def input_port(name, type)
        add_port(name, :input, type)
      end

      # Declares an output port: +output_port 'samples', '/base/Pose'+.
      def output_port(name, type)
        add_port(name, :output, type)
      end

      # Timing information real bundles write (+worstcase_processing_time 0.2+):
      # recorded, and used to size buffers.
      def worstcase_processing_time(seconds = nil)
        return @timing[:worstcase_processing_time] if seconds.nil?

        @timing[:worstcase_processing_time] = seconds
      end

      # Adds the port +port+ and its reader (+pose_port+, a Models::Port of
      # this model, as Syskit's models have), unless a method of that name
      # exists.
      def add_port_entry(port)
        ports[port.name] = port
        reader = "#{port.name}_port"
        define_singleton_method(reader) { find_port(port.name) } unless respond_to?(reader)
        port
      end

      private

      # Applies the statement's options, provides +root+, then evaluates the
      # declaration block.
      def declare(root, options, block)
        apply_options(**options)
        made_from(root)
        provides(root) unless equal?(root)
        instance_eval(&block) if block
        finalize_declaration
        self
      end

      def add_port(name, direction, type)
        location = Location.of_caller
        name = name.to_s
        if ports.key?(name)
          raise DeclarationError.new("#{self} already has a port named '#{name}'",
                                     location: location, hint: 'give each port its own name')
        end

        port = add_port_entry(Orogen::Port.new(name, direction, Models.resolve_type(type, location),
                                               declared_type: type, location: location))
        PortModifiers.new(port)
      end
    end

    # Syskit's +Syskit::Models.is_model?(object)+: whether +object+ is a
    # model (a service, device or bus model, a task or composition model,
    # a service bound to one of them).
    def self.is_model?(object) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
      object.is_a?(DataServiceModel) || object.is_a?(BoundDataService) ||
        (object.is_a?(Class) && object <= Syskit::AbstractComponent) ||
        (object.is_a?(Module) && object.singleton_class.include?(Compat::NotModelledModel))
    end

    # The model of type names in declarations: a Types::Type, or a name the
    # loaded app's type registry knows.
    def self.resolve_type(type, location)
      return type if type.is_a?(Types::Type)

      app = Syskit.app
      unless app
        raise DeclarationError.new("cannot resolve the type name #{type} without a loaded app",
                                   location: location, hint: 'pass a type object instead')
      end

      app.types.resolve(type, location: location)
    end
  end
end
