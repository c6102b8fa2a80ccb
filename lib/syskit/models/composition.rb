# frozen_string_literal: true

require 'syskit/models/composition_child'
require 'syskit/models/composition_configurations'
require 'syskit/models/composition_ports'
require 'syskit/models/composition_specializations'
require 'syskit/models/composition_lookups'
require 'syskit/models/composition_dynamic_services'

module Syskit
  # The class-level side of components (see Composition).
  module Models
    # The class-level side of compositions (+class ArmControl <
    # Syskit::Composition+): children by role, exported ports, connections
    # between children, provided services, arguments, named
    # configurations and specializations, as Syskit's Models::Composition.
    #
    #   class ArmControl < Syskit::Composition
    #     argument :speed, default: 0.5
    #     add Services::JointsController, as: 'controller'
    #     add Devices::Arm, as: 'arm'
    #     controller_child.command_out_port.connect_to arm_child.joints_cmd_port
    #     export controller_child.setpoint_port
    #   end
    #
    # Each child is reachable as +name_child+, on the model (the
    # CompositionChild) and on its instances (the child's task).
    module Composition
      include Component
      include CompositionPorts
      include CompositionSpecializations
      include CompositionLookups
      include CompositionConfigurations
      include CompositionDynamicServices

      # Options of +add+ that only matter to Roby's runtime (what the
      # child's events mean to the composition): accepted, not modelled.
      RUNTIME_OPTIONS = %i[success failure remove_when_done consider_in_pending roles].freeze

      # Where the model was declared.
      attr_reader :declared_at

      def inherited(submodel)
        super
        submodel.instance_variable_set(:@declared_at, Location.of_caller)
        submodel.send(:inherit_specializations, self)
        Models.register_model(submodel)
      end

      # Its documentation: given with +doc+, else the comment block above
      # the class statement.
      def doc(text = nil)
        return super if text

        @doc ||= (Actions::Profile.doc_above(declared_at) if declared_at && !specialization?)
      end

      def to_s
        name || "anonymous composition (#{declared_at})"
      end

      def inspect
        to_s
      end

      def short_name
        to_s
      end

      # Adds the child +as+ requiring +models+ (a task, composition, service
      # or device model, a list of them, or requirements such as
      # +Model.with_arguments(...)+). Adding again a child of a parent
      # model overloads it (see #overload).
      def add(models, as: nil, **options)
        location = Location.of_caller
        name = Arguments.name(as, statement: 'add', what: 'a child name (as:)', pattern: Arguments::METHOD_NAME,
                                  example: "add #{models.inspect}, as: 'name'")
        runtime = options.keys & RUNTIME_OPTIONS
        unknown = options.keys - RUNTIME_OPTIONS
        unless unknown.empty?
          raise DeclarationError.new("unknown option #{unknown.map { |o| "#{o}:" }.join(', ')} for add",
                                     location: location, hint: "add takes the child's model and as: 'name'")
        end
        Syskit.app&.not_modelled("add's #{runtime.join(', ')} option", location) unless runtime.empty?

        add_child(name, requirements_of(models, location), location)
      end

      # Adds a child and marks it as the composition's main task (its end
      # is the composition's, at runtime). One per composition, a parent
      # model's included: a submodel does not replace it.
      def add_main(models, **options)
        if (main = main_task)
          inherited = " (from #{main.composition_model})" unless own_main_child
          raise DeclarationError.new("#{self} already has a main child (#{main.child_name})#{inherited}",
                                     location: Location.of_caller, hint: 'use add for the other children')
        end

        @main_child = add(models, **options)
      end
      alias add_main_task add_main

      # The main child (see #add_main), inherited ones included.
      def main_task
        own_main_child || (superclass.main_task if superclass.respond_to?(:main_task))
      end

      # Adds a child that stays out of the network when nothing is selected
      # for it.
      def add_optional(models, **options)
        add(models, **options).optional
      end

      # Refines an existing child (of this model or a parent model): the
      # child then requires +model+ too, which must be compatible with what
      # it required (a submodel, or a service next to the others).
      def overload(child, model, **options)
        name = child.respond_to?(:child_name) ? child.child_name : child.to_s
        unless find_child(name)
          raise DeclarationError.new(
            "#{name} is not a child of #{self}#{Naming.did_you_mean(name, child_names)}",
            location: Location.of_caller, hint: "children are #{child_names.join(', ')}; use add to add one"
          )
        end

        add(model, as: name, **options)
      end

      # Children by name, inherited ones included.
      def children
        own = @children || {}
        return own unless superclass.respond_to?(:children)

        superclass.children.each_with_object({}) do |(name, child), all|
          all[name] = own[name] || promoted_child(name, child)
        end.merge(own)
      end

      def each_child(&block)
        return enum_for(__method__) unless block

        children.each(&block)
      end

      def child_names
        children.keys
      end
      alias children_names child_names

      # The child named +name+ (nil when there is none).
      def find_child(name)
        name = name.to_s
        (@children && @children[name]) ||
          (promoted_child(name, superclass.find_child(name)) if superclass.respond_to?(:find_child))
      end

      # The +x_child+ readers of this model's children (its parents'
      # included), as a module the CompositionChild objects standing for a
      # composition of this model extend: a child added later is readable
      # on them too.
      def child_readers
        @child_readers ||= Module.new.tap do |readers|
          readers.include(superclass.child_readers) if superclass.respond_to?(:child_readers)
        end
      end

      # Requirements of this model (see InstanceRequirements).
      def to_instance_requirements
        InstanceRequirements.new([self], declared_at: Location.of_caller)
      end

      # +Cmp.use(...)+: the composition with dependency injection.
      def use(*mappings)
        location = Location.of_caller
        InstanceRequirements.new([self], declared_at: location).use(*mappings)
      end

      # Which specializations to prefer when several apply.
      def prefer_specializations(hints)
        InstanceRequirements.new([self], declared_at: Location.of_caller).prefer_specializations(hints)
      end

      # Whether the instances can be put in a network: compositions always
      # can (their children are checked when they are instantiated).
      def component_model?
        true
      end

      private

      def own_main_child
        @main_child
      end

      def requirements_of(models, location)
        unless InstanceRequirements.selectable?(models)
          raise DeclarationError.new(
            "add expects a task, composition, service or device model, got #{Arguments.shown(models)}",
            location: location, hint: "write add OroGen.library.Task, as: 'name' (or a data service model)"
          )
        end

        InstanceRequirements.from(models, location: location)
      end

      def add_child(name, requirements, location)
        existing = find_child(name)
        facets = existing ? facets_of(existing, requirements) : []
        requirements = overloaded(existing, requirements, location) if existing
        child = CompositionChild.new(self, name, requirements, location, optional: existing&.optional? || false,
                                                                         facets: facets - requirements.models,
                                                                         parent_model: overloaded_child(existing))
        (@children ||= {})[name] = child
        Component.declarations_changed # see #port_connections and #exports
        define_child_readers(name)
        child
      end

      # The child of a parent model that +existing+ (the child being
      # overloaded) stands for: Syskit's parent_model of the new child.
      def overloaded_child(existing)
        return unless existing
        return existing.parent_model if existing.equal?(@children&.[](existing.child_name))

        superclass.find_child(existing.child_name)
      end

      # The models +existing+ is known as, which an overload with
      # +requirements+ may fold into a model that fullfills them: the child
      # keeps their ports (+pose_port+ of a Pose child overloaded with a
      # task providing Pose), so that what was written against them still
      # holds.
      def facets_of(existing, requirements)
        (existing.facets + existing.models + requirements.models).grep(DataServiceModel).uniq
      end

      # The requirements of +existing+ refined by +requirements+.
      def overloaded(existing, requirements, location)
        models = Models.merge_models(existing.models, requirements.models, location, existing)
        merged = existing.requirements.merge_selection(requirements)
        InstanceRequirements.new(models, arguments: existing.arguments.merge(requirements.arguments),
                                         conf: requirements.conf_given? ? requirements.conf : nil,
                                         conf_location: requirements.conf_location,
                                         deployment_hints: merged.deployment_hints, deployment: merged.deployment,
                                         selections: merged.selections, declared_at: location)
      end

      # +name_child+ on the model, on its instances and on the children
      # standing for a composition of this model (see #child_readers).
      def define_child_readers(name)
        reader = "#{name}_child"
        define_singleton_method(reader) { find_child(name) } unless singleton_class.method_defined?(reader)
        define_method(reader) { child_task(name) } unless method_defined?(reader)
        child_readers.define_method(reader) { find_child(name) } unless CompositionChild.method_defined?(reader)
      end

      # A parent's child seen from this model (kept, so that it is the same
      # object each time).
      def promoted_child(name, child)
        return unless child

        (@promoted ||= {})[name] ||= child.promote(self)
      end
    end

    # +existing+ models refined with +added+: a model that fullfills one of
    # the existing ones replaces it; an unrelated service is added; two
    # unrelated component models are an error.
    def self.merge_models(existing, added, location, child)
      added.each_with_object(existing.dup) do |model, result|
        next if result.any? { |m| m.fullfills?(model) }

        refined = result.select { |m| model.fullfills?(m) }
        next result[result.index(refined.first)] = model if refined.size == 1
        next result.replace(result - refined) << model unless refined.empty?

        other = result.find { |m| m.is_a?(Class) } if model.is_a?(Class)
        raise unrelated_models(child, other, model, location) if other

        result << model
      end
    end

    def self.unrelated_models(child, other, model, location)
      DeclarationError.new("#{child} cannot be both a #{other} and a #{model}",
                           location: location, hint: "overload it with a submodel of #{other}, or with a data service")
    end
  end
end
