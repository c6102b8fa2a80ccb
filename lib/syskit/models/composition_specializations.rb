# frozen_string_literal: true

require 'syskit/models/specialization_mappings'
require 'syskit/models/composition_specialization'
require 'syskit/models/specialization_manager'

module Syskit
  module Models
    # Specializations of composition models, as Syskit's:
    #
    #   specialize controller_child => Services::OpenLoopController do
    #     export controller_child.command_in_port
    #   end
    #
    # When the components chosen for the children fullfill what a
    # specialization names, the composition is instantiated as a submodel
    # on which the specialization's block ran. Several specializations that
    # apply together are merged into one submodel, unless a constraint
    # (+add_specialization_constraint { |a, b| ... }+) says they cannot be
    # combined; then the choice is ambiguous (an error), unless
    # +prefer_specializations+ picks one. Part of Composition.
    module CompositionSpecializations
      include SpecializationMappings

      # Declares a specialization (see the module's documentation). Children
      # are given as +name_child+ objects or names; the value is a model or
      # a list of models. Without mappings, a private submodel is made and
      # the block evaluated on it.
      def specialize(mappings = {}, &block)
        location = Location.of_caller
        return private_specialization(&block) if mappings.empty?

        mappings = without_not_option(mappings, location)
        children = normalize_specialization(mappings, location)
        spec = own_specializations.find { |s| s.specialized_children == children }
        unless spec
          spec = CompositionSpecialization.declared(children, self, location)
          record_compatibilities(spec)
          own_specializations << spec
        end
        spec.specialization_blocks << block if block
        @specialized_models = nil
        check_specialization_block(spec, block) if block
        spec
      end

      # The specializations of this model, its parents' included (a
      # SpecializationManager, as Syskit's).
      def specializations
        inherited = superclass.respond_to?(:specializations) ? superclass.specializations.to_a : []
        promoted = inherited.map { |spec| (@promoted_specs ||= {}.compare_by_identity)[spec] ||= spec.promote(self) }
        SpecializationManager.new(self, promoted + own_specializations)
      end

      # Whether this model or a parent declares a specialization, without
      # making the SpecializationManager: asked for every composition
      # while generating, and most models have none.
      def specializations?
        return true if @own_specializations && !@own_specializations.empty?

        superclass.respond_to?(:specializations?) && superclass.specializations?
      end

      # Adds a constraint on which specializations may be combined: the
      # block gets two specializations and says whether they can apply
      # together. It must give the same answer both ways.
      def add_specialization_constraint(explicit = nil, &block)
        (@specialization_constraints ||= []) << (explicit || block)
      end

      def specialization_constraints
        inherited = superclass.respond_to?(:specialization_constraints) ? superclass.specialization_constraints : []
        inherited + (@specialization_constraints || [])
      end

      # For a specialized model, the specializations applied to make it
      # (a Set, as Syskit's).
      def applied_specializations
        return @applied_specializations if @applied_specializations

        superclass.respond_to?(:applied_specializations) ? superclass.applied_specializations : NO_SPECIALIZATIONS
      end

      NO_SPECIALIZATIONS = Set.new.freeze

      # The model a specialized model was made from (itself otherwise).
      def specialization_root
        @specialization_root || self
      end

      # A specialized model fullfills another made from the same root when
      # it has at least its specializations (so do its submodels).
      def fullfills?(model)
        return true if super
        return false unless model.is_a?(Class) && model.respond_to?(:specialization?) && model.specialization?

        self <= model.specialization_root && (model.applied_specializations - applied_specializations).empty?
      end
      alias fulfills? fullfills?

      # For a specialized model, the models its children are specialized on.
      def specialized_children
        @specialized_children || {}
      end

      def specialization?
        !@applied_specializations.nil?
      end
      alias is_specialization? specialization?

      # The composition model to instantiate for +selection+ (child name =>
      # selected requirements): this one, or a specialized submodel.
      # +hints+: prefer_specializations' mappings.
      def specialized_model_for(selection, hints: [], location: nil)
        return self if specialization? || !specializations?

        candidates = specialization_candidates(specializations.select { |s| s.weak_match?(selection) })
        candidates = prefer(candidates, hints) if candidates.size > 1
        return self if candidates.empty?
        raise ambiguous_specialization(candidates, selection, location) if candidates.size > 1

        specialized_model(candidates.first)
      end

      # The specialized submodel on which +specs+ applied, made once.
      def specialized_model(specs)
        key = specs.map(&:object_id).sort
        (@specialized_models ||= {})[key] ||= build_specialized_model(specs)
      end

      # The model selected by injection +context+ (a Hash, a
      # DependencyInjection or a context), as Syskit's +narrow+ (selections
      # by child name may also be given as the last arguments).
      def narrow(context = nil, hints: [], specialization_hints: nil, **by_name)
        context = Network::Selection.context_from(context || by_name.transform_keys(&:to_s))
        selection = child_names.to_h do |name|
          [name, Network::Selection.for_child(self, name, context)]
        end.compact
        specialized_model_for(selection.compact, hints: specialization_hints || hints)
      end

      private

      def own_specializations
        @own_specializations ||= []
      end

      # Two specialized models of one composition model merge into the
      # specialized model with the specializations of both applied.
      def merged_specializations(other)
        return unless specialization? && other.respond_to?(:specialization?) && other.specialization? &&
                      specialization_root.equal?(other.specialization_root)

        specialization_root.specialized_model(applied_specializations | other.applied_specializations)
      end

      # A submodel of its own, named after this model, on which +block+ is
      # evaluated (see Component#private_specialization?).
      def private_specialization(&block)
        @private_specialization_count = (@private_specialization_count || 0) + 1
        model = new_submodel(name: "#{self}{#{@private_specialization_count}}")
        model.instance_variable_set(:@private_specialization, true)
        model.class_eval(&block) if block
        model
      end

      # Syskit's +not:+ option of specialize, which its selection does not
      # use either: accepted, with a warning.
      def without_not_option(mappings, location)
        return mappings unless mappings.key?(:not)

        Syskit.app&.not_modelled("specialize's not: option", location)
        mappings.except(:not)
      end

      # Runs the block on the specialized model now, as Syskit does, so
      # that its mistakes are found where it is written rather than when a
      # network selects it; the model is made again when selected.
      def check_specialization_block(spec, block)
        specialized_model([spec])
      rescue StandardError
        spec.specialization_blocks.delete(block)
        raise
      ensure
        @specialized_models = nil
      end

      # Groups of specializations that apply together: one per
      # specialization, with every later one compatible with the group.
      def specialization_candidates(matching)
        groups = matching.map { |spec| compatible_group(spec, matching) }.uniq
        groups.reject { |g| groups.any? { |other| other != g && (g - other).empty? } }
      end

      # +spec+ and each of +matching+ compatible with all those before, in
      # declaration order.
      def compatible_group(spec, matching)
        group = matching.each_with_object([spec]) do |other, found|
          found << other if !found.include?(other) && found.all? { |s| compatible?(s, other) }
        end
        group.sort_by { |s| matching.index(s) }
      end

      # Which of the existing specializations +spec+ can be combined with
      # (the constraints decide), recorded on both sides.
      def record_compatibilities(spec)
        own_specializations.each do |other|
          next unless compatible?(other, spec)

          other.compatibilities << spec
          spec.compatibilities << other
        end
      end

      def compatible?(one, other)
        specialization_constraints.all? do |constraint|
          result = constraint.call(one, other)
          unless result == constraint.call(other, one)
            raise DeclarationError.new("the specialization constraint of #{self} is not symmetric " \
                                       "for #{one} and #{other}", location: declared_at,
                                                                  hint: 'a constraint must say the same both ways')
          end

          result
        end
      end

      def prefer(candidates, hints)
        return candidates if hints.empty?

        preferred = candidates.select do |group|
          hints.any? { |hint| group.any? { |spec| spec.weak_match?(hint_selection(hint)) } }
        end
        preferred.empty? ? candidates : preferred
      end

      # prefer_specializations' mappings as a selection (names => models).
      def hint_selection(hint)
        hint.to_h do |child, models|
          name = child.respond_to?(:child_name) ? child.child_name : child.to_s
          [name, InstanceRequirements.from(models)]
        end
      end

      def ambiguous_specialization(candidates, selection, location)
        choices = candidates.map { |group| group.join(' + ') }
        selected = selection.map { |name, sel| "#{name} => #{sel}" }.join(', ')
        NetworkError.new(
          "several specializations of #{self} apply to #{selected} and cannot be combined: #{choices.join('; ')}",
          location: location || declared_at,
          hint: 'choose one with prefer_specializations(child_child => Model) on the requirements'
        )
      end

      def build_specialized_model(specs)
        model = Class.new(self)
        children = specs.each_with_object({}) do |spec, all|
          spec.specialized_children.each { |name, models| all[name] = ((all[name] || []) + Array(models)).uniq }
        end
        model.send(:become_specialization, specs, children, self)
        children.each { |name, models| model.overload(name, models) }
        specs.each { |spec| spec.specialization_blocks.each { |block| model.class_eval(&block) } }
        model
      end

      def become_specialization(specs, children, root)
        @specialization_root = root
        @applied_specializations = specs.to_set.freeze
        @specialized_children = children.freeze
        @declared_at = root.declared_at
        @given_name = "#{root.short_name}/" + children.map do |name, models|
          "#{name}.is_a?(#{models.join(',')})"
        end.join(',')
      end

      # A submodel starts with no specializations of its own.
      def inherit_specializations(_parent)
        @own_specializations = []
      end
    end
  end
end
