# frozen_string_literal: true

module Syskit
  # The injections in effect where a child is instantiated: the
  # profile's (its robot's devices, used profiles, +use+ statements),
  # then each enclosing requirement's +use+, later ones winning. Each
  # layer resolves its defaults against its own explicit keys
  # first, as Syskit does. #with and #mask return new contexts; Syskit's
  # #push and #pop change this one (EMPTY is frozen).
  class DependencyInjectionContext
    attr_reader :state

    # Syskit's +DependencyInjectionContext.new(injection, ...)+: the given
    # layers (DependencyInjection values, or hashes of selections as +use+
    # takes them), later ones winning.
    def self.new(*injections)
      injections.reduce(resolved({}, {})) do |context, injection|
        injection = DependencyInjection.new(injection) if injection.is_a?(Hash)
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
      @stack = []
    end

    EMPTY = resolved({}, {}).freeze

    # Adds the layer +injection+ on top (Syskit's +push+).
    def push(injection)
      @stack.push([state, @locations])
      pushed = with(injection)
      @state = pushed.state
      @locations = pushed.locations
      self
    end

    # Removes the layer pushed last.
    def pop
      @state, @locations = @stack.pop
      self
    end

    # The selections in effect, as one injection (Syskit's +current_state+).
    def current_state
      DependencyInjection.of(state)
    end

    # What is selected for the child +name+ requiring +requirements+ (see
    # DependencyInjection#selection_for).
    def selection_for(name, requirements)
      current_state.selection_for(name, requirements)
    end

    def with(injection)
      return self if injection.nil? || injection.empty?

      # A model selected for itself (what a default gives) does not
      # undo what an earlier layer selected for it, as in Syskit.
      added = DependencyInjection.resolve_default_selections(injection.explicit, injection.defaults)
      added = added.reject { |key, value| value.equal?(key) && state.key?(key) }
      locations = @locations.merge(added.transform_values { injection.declared_at })
      DependencyInjectionContext.resolved(DependencyInjection.resolve_recursive_selection_mapping(state.merge(added)),
                                          locations)
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
    # as it was selected and the keys used ([nil, []] when nothing is).
    def selected_value_for(name, models)
      if name && state.key?(name) && !state[name].equal?(DependencyInjection::DO_NOT_INHERIT)
        value = state[name]
        return [nil, [name]] if value.equal?(DependencyInjection::NOTHING)

        return [value, [name]]
      end

      models.each do |model|
        value = state[model]
        return [value, [model]] if value && !DependencyInjection.placeholder?(value)
      end
      [nil, []]
    end

    # The selection of a key (a model or tag), if any.
    def direct_selection_for(key)
      value = state[key]
      value unless DependencyInjection.placeholder?(value)
    end

    protected

    attr_reader :locations
  end
end
