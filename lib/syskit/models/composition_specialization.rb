# frozen_string_literal: true

require 'set'

module Syskit
  module Models
    # One +specialize+ statement of a composition model (or several on the
    # same children), as Syskit's CompositionSpecialization: the children it
    # specializes (name => models), its blocks, and the specializations it
    # may be combined with (+compatibilities+). A specialized model is made
    # from one or several of them (see CompositionSpecializations).
    class CompositionSpecialization
      attr_reader :root, :specialized_children, :specialization_blocks, :location, :compatibilities

      # +spec+: child name (or child) => model or models; +block+: evaluated
      # on the specialized model.
      def initialize(spec = {}, block = nil)
        @specialized_children = CompositionSpecialization.normalize(spec).freeze
        @specialization_blocks = block ? [block] : []
        @compatibilities = Set.new
      end

      # A specialization of the composition model +root+ declared at
      # +location+.
      def self.declared(spec, root, location)
        specialization = new(spec)
        specialization.instance_variable_set(:@root, root)
        specialization.instance_variable_set(:@location, location)
        specialization
      end

      # Child names as strings (the models as given: a model or a list).
      def self.normalize(spec)
        spec.transform_keys { |child| child.respond_to?(:child_name) ? child.child_name : child.to_s }
      end

      # Whether it specializes no child.
      def empty?
        specialized_children.empty?
      end

      # Adds the children +spec+ specializes (the model lists of a child
      # both name are merged) and the +blocks+.
      def add(spec, blocks)
        children = specialized_children.dup
        CompositionSpecialization.normalize(spec).each do |name, models|
          existing = children[name]
          children[name] = existing ? Models.merge_models(Array(existing), Array(models), location, name) : models
        end
        @specialized_children = children.freeze
        @specialization_blocks.concat(Array(blocks))
        self
      end

      # Combines +other+ into this one: what both are compatible with
      # (everything +other+ is, when this one is empty), +other+ itself,
      # and its children and blocks.
      def merge(other)
        @compatibilities = empty? ? other.compatibilities.dup : (compatibilities & other.compatibilities)
        @compatibilities << other
        add(other.specialized_children, other.specialization_blocks)
      end

      # Whether it can be applied together with +other+.
      def compatible_with?(other)
        empty? || other.empty? || equal?(other) || compatibilities.include?(other)
      end

      # The same specialization on +model+ (a submodel of its root).
      def promote(model)
        promoted = CompositionSpecialization.declared(specialized_children, model, location)
        promoted.specialization_blocks.concat(specialization_blocks)
        promoted.compatibilities.merge(compatibilities)
        promoted
      end

      # Whether +selection+ (child name => the selected requirements or
      # models) fullfills what the specialization names for at least one
      # child, and contradicts it for none.
      def weak_match?(selection)
        matched = false
        specialized_children.each do |name, models|
          selected = selection[name]
          next unless selected

          selected = Array(selected)
          return false unless Array(models).all? { |m| selected.any? { |s| CompositionSpecialization.match?(s, m) } }

          matched = true
        end
        matched
      end

      # Whether +selected+ (requirements or a model) fullfills +model+ for
      # a specialization: through its service when one is selected, as in
      # Syskit (a task that provides both X and Y, selected through its X
      # service, matches a specialization on X, not one on Y).
      def self.match?(selected, model)
        service = selected.service if selected.is_a?(InstanceRequirements)
        return selected.fullfills?(model) unless service
        return service.fullfills?(model) if model.is_a?(DataServiceModel)

        selected.component_model.fullfills?(model)
      end

      # Syskit's lookup for specialization constraint blocks: the models
      # specialized on +child_name+ that fullfill +model+, or nil.
      def find_specialization(child_name, model)
        found = Array(specialized_children[child_name.to_s]).select { |m| m.fullfills?(model) }
        found unless found.empty?
      end

      def has_specialization?(child_name, model) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        !find_specialization(child_name, model).nil?
      end

      # The specialized model (made from this specialization alone).
      def composition_model
        root.specialized_model([self])
      end

      def to_s
        "#{root&.short_name}/" + specialized_children.map do |name, models|
          "#{name}.is_a?(#{Array(models).join(',')})"
        end.join(',')
      end
      alias inspect to_s
    end
  end
end
