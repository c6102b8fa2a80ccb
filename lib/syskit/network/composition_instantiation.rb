# frozen_string_literal: true

module Syskit
  module Network
    # How Instantiate makes a composition: its children selected through
    # dependency injection (see Selection), the composition specialized on
    # what was selected, then each child instantiated in turn, in the
    # context its selection leaves. Part of Instantiate: uses its stack of
    # the compositions being built (+@building+), +@stub_abstract+, and its
    # +instantiate+ for each child.
    module CompositionInstantiation
      private

      def instantiate_composition(model, requirements, context, path, parent)
        selections = select_children(model, context)
        specialized = specialize(model, selections, requirements)
        return instantiate_composition(specialized, requirements, context, path, parent) if specialized != model
        raise abstract(requirements, path, parent, model) if model.abstract? && !@placeholders

        composition = model.new(task_arguments(requirements, parent))
        Instantiate.assign_conf(composition, requirements)
        composition.name = path
        composition.requirements = requirements
        composition.parent = parent
        @building.push(composition)
        instantiate_children(composition, selections, requirements, context)
        @context.compositions << composition
        composition
      ensure
        @building.pop if composition
      end

      def select_children(model, context)
        model.child_names.to_h { |name| [name, Selection.select(model.find_child(name), context)] }
      end

      # Explicit (by name) selections choose first, as in Syskit.
      def specialize(model, selections, requirements)
        hints = requirements.specialization_hints
        explicit = selections.select { |_, r| r.explicit && !r.reference }.transform_values(&:requirements)
        chosen = model.specialized_model_for(explicit, hints: hints, location: requirements.declared_at)
        return chosen if chosen != model

        all = selections.reject { |_, r| r.reference }.transform_values(&:requirements)
        model.specialized_model_for(all, hints: hints, location: requirements.declared_at)
      end

      # Children referring to a sibling (+use(srv => first_child)+) come
      # after it.
      def instantiate_children(composition, selections, requirements, context)
        pending = selections.keys
        until pending.empty?
          ready = pending.reject { |name| waits_for_sibling?(composition, selections[name]) }
          raise sibling_cycle(composition, pending) if ready.empty?

          ready.each do |name|
            instantiate_child(composition, name, selections[name], requirements, context)
          end
          pending -= ready
        end
      end

      def waits_for_sibling?(composition, selection)
        references(selection).any? do |ref|
          ref = ref.referenced_child.outermost_child
          owner = @building.reverse.find { |c| c.model.fullfills?(ref.composition_model) }
          owner.equal?(composition) && !composition.has_role?(ref.child_name)
        end
      end

      # Children of compositions a selection refers to.
      def references(selection)
        found = [selection.reference].compact
        selection.requirements.selections.explicit.each_value { |v| found << v if v.is_a?(Models::ChildReference) }
        found
      end

      def instantiate_child(composition, name, selection, requirements, context)
        child = composition.model.find_child(name)
        return add_referenced_child(composition, name, selection.reference) if selection.reference

        child_requirements = with_composition_conf(composition, name, selection.requirements)
        return if child.optional? && child_requirements.abstract? && !@stub_abstract

        child_context = child_context(context, selection, requirements, name, child_requirements)
        task = instantiate(child_requirements, child_context, "#{composition.name}.#{name}", composition)
        composition.add_child(name, task)
        composition.child_selection[name] = InstanceSelection.new(task, child_requirements, child.requirements)
      end

      # The child +name+ is the task of another child (+reference+).
      def add_referenced_child(composition, name, reference)
        requirements = referenced_requirements(reference)
        composition.add_child(name, requirements.instance)
        required = composition.model.find_child(name).requirements
        composition.child_selection[name] = InstanceSelection.new(requirements.instance, requirements, required)
      end

      # The context a child's own children are selected in: without what
      # selected the child, with the enclosing requirements' selections
      # for its children ('child.grandchild' keys) and its own.
      def child_context(context, selection, requirements, name, child_requirements)
        grandchildren = context.grandchild_selections(name).merge(requirements.selections.grandchild_selections(name))
        context = context.mask(selection.used_keys)
        context = context.with(DependencyInjection.of(grandchildren, [], requirements.declared_at)) unless
          grandchildren.empty?
        context.with(resolve_references(child_requirements.selections))
      end

      # Selections naming a child of an enclosing composition select its task.
      def resolve_references(selections)
        return selections unless selections.explicit.each_value.any?(Models::ChildReference)

        explicit = selections.explicit.transform_values do |value|
          value.is_a?(Models::ChildReference) ? referenced_requirements(value) : value
        end
        DependencyInjection.of(explicit, selections.defaults, selections.declared_at)
      end

      def referenced_task(child)
        referenced_owner(child).children_by_role[child.child_name] || missing_child(child, referenced_owner(child))
      end

      # What a selection naming +child+ selects: its task, through the
      # service selected for that child when there was one (the most
      # narrowed information, as in Syskit).
      def referenced_requirements(reference)
        child = reference.referenced_child
        task = referenced_task(child)
        selection = referenced_owner(child).child_selection[child.child_name]
        service = reference.referenced_service || selection&.selected&.service
        InstanceRequirements.new([task.model], service: service, instance: task, declared_at: child.declared_at)
      end

      # The composition of the network being built that has +child+: an
      # enclosing one, or the child composition a child is reached through.
      def referenced_owner(child)
        if child.reached_through
          owner = referenced_task(child.reached_through)
          return owner if owner.is_a?(Composition)

          missing_child(child, owner)
        end

        @building.reverse.find { |c| c.model.fullfills?(child.composition_model) } ||
          raise(NetworkError.new("#{child} is selected, but no enclosing composition has that child",
                                 location: child.declared_at, hint: 'select a child of an enclosing composition'))
      end

      # A child that is not in the network (an optional child with nothing
      # selected).
      def missing_child(child, owner)
        raise NetworkError.new("#{child} is selected, but #{owner} has no child '#{child.child_name}' in this network",
                               location: child.declared_at,
                               hint: "select something for the optional child '#{child.path}'")
      end

      # +conf 'name', child => [...]+ of the composition applies to the
      # children that chose no sections of their own.
      def with_composition_conf(composition, name, requirements)
        return requirements if requirements.conf_given?

        model = composition.model
        # The last of the composition's sections that names the child
        # (Array#rindex: no reversed copy).
        sections = composition.conf
        found = sections.rindex { |c| model.configuration(c)&.[](name) }
        return requirements unless found

        conf = sections[found]
        requirements.with_conf(*model.configuration(conf)[name], location: model.configuration_location(conf))
      end

      def sibling_cycle(composition, pending)
        NetworkError.new("the children #{pending.join(', ')} of #{composition.model} select each other",
                         location: composition.model.declared_at,
                         hint: 'a child selected for another must not depend on it')
      end
    end
  end
end
