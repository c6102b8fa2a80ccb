# frozen_string_literal: true

require 'syskit/dependency_injection_context'

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

    # Selects for a child by model only, whatever selects for its name
    # around it (Syskit's +DependencyInjection.do_not_inherit+).
    DO_NOT_INHERIT = Object.new
    def DO_NOT_INHERIT.to_s
      'do_not_inherit'
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

    def self.do_not_inherit
      DO_NOT_INHERIT
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

            key = normalize_key(key, location)
            explicit[key] = check_model_selection(key, check_value(value, key, location), location)
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
      when Models::CompositionChild then key.path
      when Models::DataServiceModel, Actions::Profile::Tag then key
      else
        return key if key.is_a?(Class) && key < AbstractComponent

        raise DeclarationError.new(
          "use cannot select for #{key.inspect}: keys are child names or models",
          location: location, hint: "write use('child_name' => Model) or use(Services::Pose => Model)"
        )
      end
    end

    # What is selected for a model must be that model or fullfill it (a
    # submodel of a component model, a service providing a service model),
    # as Syskit checks when +use+ is called. What class hierarchies and
    # service models say is checked here; what a component provides may
    # be declared by a file loaded later, and is checked where the
    # selection fills a child.
    def check_model_selection(key, value, location)
      return value if !key.is_a?(Module) || value.equal?(NOTHING) || value.equal?(DO_NOT_INHERIT) ||
                      selection_of_model?(key, value)

      raise DeclarationError.new("use cannot select #{Arguments.shown(value)} for #{key}: it is not a #{key}",
                                 location: location, hint: "select #{key} itself, or #{
                                   key.is_a?(Class) ? 'a submodel of it' : 'a data service that provides it'}")
    end

    # Whether +value+ can be selected for +key+, a component or service
    # model, as far as can be told while files load.
    def selection_of_model?(key, value)
      if key.is_a?(Class)
        return true unless [Module, InstanceRequirements, Models::BoundDataService].any? { |kind| value.is_a?(kind) }

        component = InstanceRequirements.from(value).component_model
        component.is_a?(Class) && component <= key
      else
        !(key.is_a?(Models::DataServiceModel) && value.is_a?(Models::DataServiceModel)) || value.fullfills?(key)
      end
    end

    def check_value(value, key, location)
      return value if value.equal?(NOTHING) || value.equal?(DO_NOT_INHERIT) || InstanceRequirements.selectable?(value)

      what = key ? "for #{key_name(key)}" : 'as a default'
      raise DeclarationError.new(
        "use cannot select #{Arguments.shown(value)} #{what}: it is not a model, device or definition",
        location: location,
        hint: 'select a task or composition model, a data service, a device (Base.gps_dev), a definition ' \
              '(Base.x_def) or a requirement (Model.with_arguments(...))'
      )
    end
  end
end
