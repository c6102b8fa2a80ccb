# frozen_string_literal: true

module Syskit
  module Models
    # Finding a composition's children by the names users write: the keys
    # of +use+ ('arm', 'control.arm' for a child of a child composition),
    # and the +x_child+ readers. A name no child has is an error that says
    # which children there are. Part of Composition.
    module CompositionLookups
      # Checks that each of +keys+ (the string keys of a +use+) names a
      # child, as Syskit does: a child of this model or of one of its
      # specializations ('control.arm': the child 'control'; what it has
      # depends on what is selected for it).
      def check_child_keys(keys, location)
        keys.each do |key|
          name = key.split('.').first
          raise unknown_child(name, key, location) unless find_child_anywhere(name)
        end
      end

      # Checks that what +selections+ (child name => value) select for
      # this model's children is a submodel of the component model each
      # requires, as Syskit does when +use+ is called (what services a
      # component provides may be declared later, and is checked where the
      # selection fills the child).
      def check_child_selections(selections, location)
        selections.each do |name, value|
          child = find_child(name)
          required = child&.requirements&.component_model
          next unless required.is_a?(Class) && InstanceRequirements.selectable?(value)

          selected = InstanceRequirements.from(value).component_model
          next if !selected.is_a?(Class) || selected <= required

          raise InvalidSelection.new("#{selected} cannot be selected for the child '#{name}' of #{self}: " \
                                     "it is not a #{required}",
                                     location: location, hint: "select a #{required} (or a submodel of it)")
        end
      end

      # The child +name+ of this model or, when it has none, of one of its
      # specializations (+specialize ... do add X, as: 'extra' end+).
      def find_child_anywhere(name)
        find_child(name) || specializations.lazy.filter_map { |s| s.composition_model.find_child(name) }.first
      end

      # What +context+ (selections, see Network::Selection.context_from)
      # selects for each child, as Syskit's +find_children_models_and_tasks+:
      # [the InstanceSelection of each child selected by name, that of every
      # child, the keys of +context+ each child used], by child name.
      def find_children_models_and_tasks(context)
        context = Network::Selection.context_from(context)
        explicit = {}
        all = {}
        used = {}
        each_child do |name, child|
          result = Network::Selection.select(child, context)
          all[name] = InstanceSelection.new(result.requirements.instance, result.requirements, child.requirements)
          explicit[name] = all[name] if result.explicit
          used[name] = result.used_keys
        end
        [explicit, all, used]
      end

      # The error for +name+ (a part of the +use+ key +key+), which is no
      # child of this model.
      def unknown_child(name, key, location)
        names = child_names
        DeclarationError.new(
          "#{name} is not a child of #{self}#{Naming.did_you_mean(name, names)}" \
          "#{" (in use('#{key}' => ...))" unless name == key}",
          location: location, hint: names.empty? ? "#{self} has no children" : "its children: #{names.join(', ')}"
        )
      end

      # Why +name+ is not a method of the model, when it is a child's
      # reader (+x_child+); nil otherwise (see UserCode.explain).
      def explain_missing(name)
        return unless name.end_with?('_child')

        child = name.delete_suffix('_child')
        names = child_names
        ["#{self} has no child '#{child}'#{Naming.did_you_mean(child, names)}",
         names.empty? ? "add one: add Model, as: '#{child}'" : "its children: #{names.join(', ')}"]
      end
    end
  end
end
