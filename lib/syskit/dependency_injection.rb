# frozen_string_literal: true

module Syskit
  # What +use+ says: which model, device or definition to put in place of a
  # composition's children (Syskit's dependency injection).
  #
  #   Cmp.use('pose' => Base.gps_dev)          # by child name
  #   Cmp.use(Services::Pose => OroGen.gps.Task) # any child requiring Pose
  #   Cmp.use(OroGen.gps.Task)                 # a default: every child it can fill
  #
  # A value: explicit selections by key (a child name, or a model) and
  # defaults (values without a key, which select themselves for every model
  # they fullfill, unless that is ambiguous). Adding returns a new one.
  class DependencyInjection
    # Selects nothing for a child: it keeps the model it was added with
    # (Syskit's +DependencyInjection.nothing+).
    NOTHING = Object.new
    def NOTHING.to_s
      'nothing'
    end

    attr_reader :explicit, :defaults, :declared_at

    def initialize(explicit = {}, defaults = [], declared_at = nil)
      @explicit = explicit.freeze
      @defaults = defaults.freeze
      @declared_at = declared_at
      freeze
    end

    EMPTY = new

    def self.nothing
      NOTHING
    end

    def empty?
      explicit.empty? && defaults.empty?
    end

    # A new injection with +mappings+ (hashes of key => value, and values
    # without a key) added; later keys override earlier ones.
    def add(mappings, location)
      explicit = self.explicit.dup
      defaults = self.defaults.dup
      mappings.each do |mapping|
        next if not_modelled?(mapping, location)

        if mapping.is_a?(Hash)
          mapping.each do |key, value|
            next if not_modelled?(key, location) || not_modelled?(value, location)

            explicit[normalize_key(key, location)] = check_value(value, key, location)
          end
        else
          defaults << check_value(mapping, nil, location)
        end
      end
      DependencyInjection.new(explicit, defaults, location)
    end

    # Selections of the children of child +name+, from the keys
    # 'name.grandchild' (by grandchild name).
    def grandchild_selections(name)
      prefix = "#{name}."
      explicit.each_with_object({}) do |(key, value), result|
        result[key.delete_prefix(prefix)] = value if key.is_a?(String) && key.start_with?(prefix)
      end
    end

    def to_s
      parts = explicit.map { |k, v| "#{key_name(k)} => #{v}" } + defaults.map(&:to_s)
      "use(#{parts.join(', ')})"
    end
    alias inspect to_s

    private

    # A value made by a statement this gem does not model (the device of
    # use_gazebo_model): the selection is left out, with a warning.
    def not_modelled?(value, location)
      return false unless Compat::Ignored === value # rubocop:disable Style/CaseEquality

      Syskit.app&.not_modelled('a selection of something not modelled', location)
      true
    end

    def key_name(key)
      key.is_a?(String) ? "'#{key}'" : key.to_s
    end

    def normalize_key(key, location)
      case key
      when String, Symbol then key.to_s
      when Models::CompositionChild then key.child_name
      when Models::DataServiceModel, Profile::Tag then key
      else
        return key if key.is_a?(Class) && key < AbstractComponent

        raise DeclarationError.new(
          "use cannot select for #{key.inspect}: keys are child names or models",
          location: location, hint: "write use('child_name' => Model) or use(Services::Pose => Model)"
        )
      end
    end

    def check_value(value, key, location)
      return value if value.equal?(NOTHING) || InstanceRequirements.selectable?(value)

      what = key ? "for #{key_name(key)}" : 'as a default'
      raise DeclarationError.new(
        "use cannot select #{Arguments.shown(value)} #{what}: it is not a model, device or definition",
        location: location,
        hint: 'select a task or composition model, a data service, a device (Base.gps_dev), a definition ' \
              '(Base.x_def) or a requirement (Model.with_arguments(...))'
      )
    end

    # The injections in effect where a child is instantiated: the
    # profile's (its robot's devices, used profiles, +use+ statements),
    # then each enclosing requirement's +use+, later ones winning. Each
    # layer resolves its defaults against its own explicit keys
    # first, as Syskit does. A frozen value; #with and #mask return new ones.
    class Context
      # Roots of the model hierarchies: fullfilled by everything, never a
      # key of a default selection.
      def self.ignored_models
        [Syskit::DataService, Syskit::Device, Syskit::ComBus, Syskit::AbstractComponent, Syskit::Component,
         Syskit::TaskContext, Syskit::Composition]
      end

      attr_reader :state

      # +locations+: where each key was selected (the +use+ statement).
      def initialize(state = {}, locations = {})
        @state = state.freeze
        @locations = locations.freeze
        freeze
      end

      EMPTY = new

      def with(injection)
        return self if injection.nil? || injection.empty?

        added = Context.resolve_defaults(injection)
        locations = @locations.merge(added.transform_values { injection.declared_at })
        Context.new(Context.follow_chains(state.merge(added)), locations)
      end

      # The context without +keys+ (the selections a child used, which
      # must not apply again to that child's own children).
      def mask(keys)
        return self if keys.empty?

        Context.new(state.except(*keys), @locations)
      end

      # Where +key+ was selected.
      def location_of(key)
        @locations[key]
      end

      # What is selected for the child +name+ requiring +models+: the value
      # and the keys used ([nil, []] when nothing is selected).
      def selection_for(name, models)
        if name && state.key?(name)
          value = state[name]
          return [nil, [name]] if value.equal?(NOTHING)

          return [value, [name]]
        end

        models.each do |model|
          value = state[model]
          return [value, [model]] if value && !value.equal?(NOTHING)
        end
        [nil, []]
      end

      # The selection of a key (a model or tag), if any.
      def direct_selection_for(key)
        value = state[key]
        value unless value.equal?(NOTHING)
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
          while (value.is_a?(Module) || value.is_a?(Profile::Tag)) && state.key?(value) && !seen.include?(value)
            seen << value
            next_value = state[value]
            break if next_value.equal?(NOTHING) || next_value.equal?(value)

            value = next_value
          end
          value
        end
      end
    end
  end
end
