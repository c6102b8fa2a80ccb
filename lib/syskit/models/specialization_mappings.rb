# frozen_string_literal: true

module Syskit
  module Models
    # What +specialize+ accepts, checked where it is written: the children
    # (a +name_child+, a name, or a model that exactly one child requires)
    # and the models they are specialized on, which must refine what the
    # child requires. Part of CompositionSpecializations.
    module SpecializationMappings
      private

      # +mappings+ as child name => models, checked.
      def normalize_specialization(mappings, location)
        mappings.to_h do |selector, models|
          name = specialized_child_name(selector, models, location)
          models = Array(models).freeze
          check_specialization_models(name, models, location)
          [name, models]
        end
      end

      def specialized_child_name(selector, models, location)
        case selector
        when CompositionChild then own_child_name(selector, location)
        when String, Symbol then known_child_name(selector.to_s, location)
        else
          return child_requiring(selector, models, location) if Models.is_model?(selector)

          raise DeclarationError.new(
            "specialize cannot select a child with #{Arguments.shown(selector)}",
            location: location, hint: "write specialize #{child_names.first || 'name'}_child => Model do ... end"
          )
        end
      end

      def own_child_name(child, location)
        return known_child_name(child.child_name, location) unless child.reached_through

        raise DeclarationError.new(
          "specialize names #{child}, a child of the child composition #{child.outermost_child}",
          location: location, hint: "specialize #{child.composition_model} itself"
        )
      end

      def known_child_name(name, location)
        return name if find_child(name)

        raise DeclarationError.new(
          "specialize names #{name}, which is not a child of #{self}#{Naming.did_you_mean(name, child_names)}",
          location: location, hint: "write specialize #{child_names.first || 'name'}_child => Model do ... end"
        )
      end

      # Syskit's +specialize Srv => Model+: the one child that requires
      # +model+.
      def child_requiring(model, specialized, location)
        found = each_child.select { |_, child| child.fullfills?(model) }.map(&:first)
        return found.first if found.size == 1

        what = "specialize #{model} => #{Arguments.shown(specialized)}"
        if found.empty?
          raise DeclarationError.new("#{what}: no child of #{self} requires #{model}",
                                     location: location, hint: 'name the child instead: specialize x_child => ...')
        end

        raise DeclarationError.new("#{what}: several children of #{self} require #{model} (#{found.join(', ')})",
                                   location: location,
                                   hint: "name the one you mean: specialize #{found.first}_child => ...")
      end

      # The models must be service or component models that refine what
      # the child requires (two unrelated task models are an error).
      def check_specialization_models(name, models, location)
        child = find_child(name)
        models.each do |model|
          next if model.is_a?(DataServiceModel) || (model.is_a?(Class) && model < AbstractComponent)

          raise DeclarationError.new(
            "specialize #{name} => #{Arguments.shown(model)}: not a task, composition or data service model",
            location: location, hint: 'specialize children on models (a service model, a task model)'
          )
        end
        merged = Models.merge_models(child.models, models, location, child)
        return unless merged.size == child.models.size && merged.all? { |m| child.models.include?(m) }

        raise DeclarationError.new(
          "specialize #{name} => #{models.join(', ')} does not specialize #{child}: it already requires #{child.model}",
          location: location, hint: 'specialize on a model that refines what the child requires'
        )
      end
    end
  end
end
