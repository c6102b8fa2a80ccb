# frozen_string_literal: true

require 'syskit/compat/ignored'
require 'syskit/compat/delayed_argument'
require 'syskit/compat/not_modelled_value'
require 'syskit/compat/eigen'
require 'syskit/compat/roby'
require 'syskit/compat/roby_task_service'
require 'syskit/compat/core_extensions'
require 'syskit/compat/task_statements'
require 'syskit/compat/conf'
require 'syskit/compat/gazebo'
require 'syskit/compat/base_float'
require 'syskit/compat/utilrb'
require 'syskit/compat/old_common_models'

module Syskit
  # Compatibility with real Rock files, in one place: the names Rock code
  # uses that are outside a devices-and-buses model layer. Each construct is
  # listed here with its effect on the plan:
  #
  # - recorded (affects the plan): Robot.requires blocks, Syskit.conf's
  #   deployment statements, Roby.app.auto_load_all_task_libraries;
  # - accepted, with one located "not modelled by this gem" warning each:
  #   Roby tasks, action interfaces, command libraries and coordination
  #   models (data monitoring tables, scripts; the classes below), runtime-only task statements
  #   (TaskStatements::RUNTIME_STATEMENTS), profile statements about compositions
  #   (Profile::NOT_MODELLED), Roby.app's runtime settings;
  # - accepted silently: what only a running system needs (use_deployment's
  #   process options).
  module Compat
    # Ruby libraries of Rock's runtime that model files require (Roby's
    # schedulers, the Gazebo bridge, Rock's Ruby types): when they are not
    # installed, requiring one is a "not modelled" warning, not an error.
    RUNTIME_LIBRARIES =
      %r{\A(roby|orocos|rock_gazebo|rock|syskit|transformer|base|concurrent|vizkit|typelib|utilrb|eigen|fipa-message)
         (/|\z)}x

    def self.runtime_library?(name)
      RUNTIME_LIBRARIES.match?(name.to_s)
    end

    # The top-level constants an active app installs besides OroGen and Types.
    def self.constants
      { Robot: Config::RobotDSL, Roby: Roby, Conf: ConfStruct.new, Typelib: Typelib, Eigen: Eigen, Orocos: Orocos,
        Utilrb: Utilrb }
    end

    # Records that a model of kind +kind+ (a composition, ...) was defined,
    # once per definition.
    def self.model_defined(kind, model, location)
      Syskit.app&.not_modelled("#{kind} #{model.name || '(anonymous)'}", location)
    end

    # Class-level behaviour of the models this gem does not model: defining
    # one is a warning, and the statements of its class body are accepted
    # as they are written, whatever they are (children, ports, events,
    # specializations: what they return is an Ignored).
    module NotModelledModel
      attr_reader :not_modelled_kind

      def inherited(subclass)
        super
        Compat.model_defined(not_modelled_kind, subclass, Location.of_caller)
      end

      # An action's description, which minitest's Kernel#describe would
      # otherwise take in test files.
      def describe(*)
        Ignored.instance
      end

      private

      # The one place where any statement is accepted: the body of a model
      # kind that this gem does not model. (Modelled code never comes here.)
      # What a statement returns is itself a not-modelled model, so that it
      # may be chained, or subclassed (+class X < Generator.for(type)+).
      def method_missing(name, *_args, **_options, &)
        return super if Ignored::CONVERSIONS.include?(name)

        IgnoredNamespace
      end

      # Calls are accepted, but nothing is advertised: code that asks
      # (respond_to?) gets the truth.
      def respond_to_missing?(_name, _include_private = false)
        false
      end

      # A constant the body names that nothing defines (an old name, a
      # model of a library that is not here): the body goes on.
      def const_missing(_name)
        IgnoredNamespace
      end
    end

    # What a not-modelled body gets for a constant nothing defines, or for
    # a statement it makes: any constant or call on it is accepted too, and
    # a class made from it is not modelled either.
    class IgnoredNamespace < NotModelledValue; end
    IgnoredNamespace.extend(NotModelledModel)
    IgnoredNamespace.instance_variable_set(:@not_modelled_kind, 'model made from a statement that is not modelled')
    IgnoredNamespace.define_singleton_method(:to_s) { '(not modelled)' }

    # oroGen's own classes, which specs sometimes call at their top level
    # (+OroGen::Spec::Deployment.register_global_initializer(:x)+): any call
    # is accepted with a "not modelled" warning naming it. On a class of
    # values (Eigen's), the call makes a value (+Eigen::Vector3.UnitZ+).
    module NotModelledCalls
      private

      def method_missing(name, *args, **options, &)
        return super if Ignored::CONVERSIONS.include?(name)

        Syskit.app&.not_modelled("#{self}.#{name}", Location.of_caller)
        return Ignored.instance unless self <= NotModelledValue

        NotModelledValue.of(self, name, options.empty? ? args : [*args, options])
      end

      def respond_to_missing?(name, _include_private = false)
        !Ignored::CONVERSIONS.include?(name)
      end
    end

    # A module of classes that take any call with a warning (see
    # NotModelledCalls), named as Rock code writes them; with +values:+,
    # classes of values made with constructor arguments (NotModelledValue).
    def self.not_modelled_namespace(shown_name, class_names, values: false, into: Module.new)
      namespace = into
      class_names.each do |name|
        klass = (values ? Class.new(NotModelledValue) : Class.new).extend(NotModelledCalls)
        full_name = "#{shown_name}::#{name}"
        klass.define_singleton_method(:to_s) { full_name }
        namespace.const_set(name, klass)
      end
      namespace
    end

    # +Typelib+: Rock's type system, which a few specs call in Ruby.
    Typelib = not_modelled_namespace('Typelib', %i[Registry Type CompoundType ContainerType EnumType OpaqueType])
    # +Typelib.from_ruby(10, type)+: the value of +type+ made from a Ruby one.
    Typelib.define_singleton_method(:from_ruby) { |value, type| type.from_ruby(value) }
    # +Utilrb::PkgConfig+: the build machine's pkg-config packages, which
    # a few specs look their C++ libraries up in (+using_library+ matters
    # only to build the component).
    Utilrb = not_modelled_namespace('Utilrb', %i[PkgConfig])
    # +OroGen::Spec+: the namespace of oroGen's specification classes.
    # Its Project and TaskContext are modelled (see compat/orogen_spec.rb).
    OrogenSpec = not_modelled_namespace('OroGen::Spec', %i[Deployment Typekit Port Operation])

    # Declares a class of a model kind this gem does not model.
    def self.not_modelled_class(namespace, name, kind)
      klass = Class.new(NotModelledValue)
      klass.extend(NotModelledModel)
      klass.instance_variable_set(:@not_modelled_kind, kind)
      namespace.const_set(name, klass)
    end

    # Syskit's task service of loggers (Roby's +task_service+).
    Syskit.const_set(:LoggerService, Roby::TaskService.new_submodel(name: 'Syskit::LoggerService'))

    # Syskit's own logger, as Rock code calls it (+Syskit.warn 'x'+), at
    # the levels of Robot's (SYSKIT_LOG).
    module Logging
      Config::RobotDSL::LEVELS.each do |level|
        define_method(level) { |message = nil, &block| Config::RobotDSL.log(level, block ? block.call : message) }
      end

      def warn_about_new_naming_convention(*)
        Config::RobotDSL.log('debug', 'a model is named with a deprecated name')
      end
    end
    Syskit.extend(Logging)

    # Syskit's network generation engine and its logging support, which
    # bundles hook into at runtime.
    Syskit.const_set(:NetworkGeneration, Module.new) unless Syskit.const_defined?(:NetworkGeneration, false)
    Syskit::NetworkGeneration.const_set(:Engine, Class.new.extend(NotModelledCalls))
    Syskit::NetworkGeneration.const_set(:LoggerConfigurationSupport, Module.new)
    not_modelled_class(Roby, :Task, 'Roby task')
    # +Roby::Task.from(:parent_task).x+, a child's argument taken from its
    # composition, is modelled as the composition's own +from+ is (see
    # TaskStatements#from).
    Roby::Task.define_singleton_method(:from) { |object| DelayedArgument.new(object) }
    # Roby's task library (Roby::Tasks::Simple, ...).
    Roby.const_set(:Tasks, Module.new)
    %i[Simple Timeout Virtual Group Parallel Sequence ExternalProcess Thread].each do |name|
      not_modelled_class(Roby::Tasks, name, 'Roby task')
    end
    # Rock's Ruby bindings of Eigen: vectors and quaternions are modelled
    # (see Compat::Eigen), the other classes make values that are not.
    not_modelled_namespace('Eigen', %i[Isometry3 AngleAxis MatrixX VectorX Matrix4 Affine3], values: true, into: Eigen)
    Roby.const_set(:Schedulers, Module.new)
    not_modelled_class(Roby::Schedulers, :Temporal, 'Roby scheduler')
    Roby.const_set(:Actions, Module.new)
    not_modelled_class(Roby::Actions, :Interface, 'action interface')
    Roby.const_set(:Interface, Module.new)
    not_modelled_class(Roby::Interface, :CommandLibrary, 'Roby command library')
    # Coordination models: what runs while tasks run (state machines,
    # scripts, data monitors).
    Roby.const_set(:Coordination, Module.new)
    %i[ActionStateMachine ActionScript TaskScript].each do |name|
      not_modelled_class(Roby::Coordination, name, 'Roby coordination model')
    end
    Syskit.const_set(:Coordination, Module.new)
    not_modelled_class(Syskit::Coordination, :DataMonitoringTable, 'data monitoring table')
    not_modelled_class(Syskit::Coordination, :TaskScript, 'task script')
  end
end

# Uses NotModelledCalls and IgnoredNamespace above.
require 'syskit/compat/orocos'
require 'syskit/compat/orogen_spec'

Syskit::TaskContext.extend(Syskit::Compat::TaskStatements)
Syskit::Composition.extend(Syskit::Compat::TaskStatements)
