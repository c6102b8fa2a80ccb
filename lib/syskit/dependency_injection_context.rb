# frozen_string_literal: true

module Syskit
  # The injections in effect where a child is instantiated: the
  # profile's (its robot's devices, used profiles, +use+ statements),
  # then each enclosing requirement's +use+, later ones winning. Each
  # layer resolves its defaults against its own explicit keys
  # first, as Syskit does. A frozen value; #with and #mask return new ones.
  class DependencyInjectionContext
    # Roots of the model hierarchies: fullfilled by everything, never a
    # key of a default selection.
    def self.ignored_models
      [Syskit::DataService, Syskit::Device, Syskit::ComBus, Syskit::AbstractComponent, Syskit::Component,
       Syskit::TaskContext, Syskit::Composition]
    end

    attr_reader :state

    # Syskit's +DependencyInjectionContext.new(injection, ...)+: the given
    # layers (DependencyInjection values, or hashes of selections as +use+
    # takes them), later ones winning.
    def self.new(*injections)
      injections.reduce(EMPTY) do |context, injection|
        injection = DependencyInjection::EMPTY.add([injection], nil) if injection.is_a?(Hash)
        context.with(injection)
      end
    end

    # The context of a resolved +state+; +locations+: where each key was
    # selected (the +use+ statement).
    def self.resolved(state, locations)
      context = allocate
      context.send(:initialize, state, locations)
      context
    end

    def initialize(state = {}, locations = {})
      @state = state.freeze
      @locations = locations.freeze
      freeze
    end

    EMPTY = resolved({}, {})

    def with(injection)
      return self if injection.nil? || injection.empty?

      # A model selected for itself (what a default gives) does not
      # undo what an earlier layer selected for it, as in Syskit.
      added = DependencyInjectionContext.resolve_defaults(injection).reject do |key, value|
        value.equal?(key) && state.key?(key)
      end
      locations = @locations.merge(added.transform_values { injection.declared_at })
      DependencyInjectionContext.resolved(DependencyInjectionContext.follow_chains(state.merge(added)), locations)
    end

    # The context without +keys+ (the selections a child used, which
    # must not apply again to that child's own children).
    def mask(keys)
      return self if keys.empty?

      DependencyInjectionContext.resolved(state.except(*keys), @locations)
    end

    # The selections by name of the children of child +name+ (the keys
    # 'name.grandchild'), by grandchild name.
    def grandchild_selections(name)
      prefix = "#{name}."
      state.each_with_object({}) do |(key, value), result|
        result[key.delete_prefix(prefix)] = value if key.is_a?(String) && key.start_with?(prefix)
      end
    end

    # Where +key+ was selected.
    def location_of(key)
      @locations[key]
    end

    # What is selected for the child +name+ requiring +models+: the value
    # and the keys used ([nil, []] when nothing is selected).
    def selection_for(name, models)
      if name && state.key?(name) && !state[name].equal?(DependencyInjection::DO_NOT_INHERIT)
        value = state[name]
        return [nil, [name]] if value.equal?(DependencyInjection::NOTHING)

        return [value, [name]]
      end

      models.each do |model|
        value = state[model]
        return [value, [model]] if value && !DependencyInjectionContext.placeholder?(value)
      end
      [nil, []]
    end

    # The selection of a key (a model or tag), if any.
    def direct_selection_for(key)
      value = state[key]
      value unless DependencyInjectionContext.placeholder?(value)
    end

    # Whether +value+ says what not to select rather than what to select
    # (nothing, do_not_inherit).
    def self.placeholder?(value)
      value.equal?(DependencyInjection::NOTHING) || value.equal?(DependencyInjection::DO_NOT_INHERIT)
    end

    # Explicit selections, with the defaults added under each model they
    # fullfill that is not selected explicitly and that no other default
    # fullfills too.
    def self.resolve_defaults(injection)
      result = injection.explicit.dup
      return result if injection.defaults.empty?

      found = {}
      ambiguous = {}
      injection.defaults.each do |value|
        InstanceRequirements.fullfilled_models_of(value).each do |model|
          next if ignored_models.include?(model) || result.key?(model) || ambiguous.key?(model)

          if found.key?(model) && !found[model].equal?(value)
            ambiguous[model] = found.delete(model)
          else
            found[model] = value
          end
        end
      end
      result.merge(found)
    end

    # A selection whose value is itself a selected key (Srv => Task,
    # Task => Task.with_arguments(...)) follows the chain.
    def self.follow_chains(state)
      state.transform_values do |value|
        seen = []
        while (value.is_a?(Module) || value.is_a?(Actions::Profile::Tag)) && state.key?(value) && !seen.include?(value)
          seen << value
          next_value = state[value]
          break if DependencyInjectionContext.placeholder?(next_value) || next_value.equal?(value)

          value = next_value
        end
        value
      end
    end
  end
end
