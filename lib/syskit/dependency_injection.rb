# frozen_string_literal: true

require 'set'
require 'syskit/dependency_injection_context'
require 'syskit/dependency_injection/selections'
require 'syskit/dependency_injection/child_selection'

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
  # they fullfill, unless that is ambiguous). Changeable as Syskit's
  # (+add+, +add_mask+, +clear+); requirements hold frozen ones.
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

    extend Selections
    include ChildSelection

    # +explicit+: selections by key (a name, a component or service model,
    # a tag); +defaults+: the values selected without a key; where the last
    # +add+ was written.
    attr_reader :explicit, :defaults, :declared_at

    # Syskit's constructor: +new(Default, 'child' => Model)+ adds what
    # #add accepts.
    def initialize(*base)
      @explicit = {}
      @defaults = Set.new
      @declared_at = nil
      add_located(base, Location.of_caller) unless base.empty?
    end

    def initialize_copy(from)
      super
      @explicit = from.explicit.dup
      @defaults = from.defaults.dup
    end

    # Frozen with its tables (what requirements hold; +dup+ gives a
    # changeable copy).
    def freeze
      @explicit.freeze
      @defaults.freeze
      super
    end

    EMPTY = new.freeze

    # A frozen injection of checked +explicit+ selections and +defaults+,
    # written at +declared_at+ (what requirements and the generator
    # combine).
    def self.of(explicit, defaults = [], declared_at = nil)
      injection = new
      injection.explicit.merge!(explicit)
      injection.add_defaults(defaults)
      injection.instance_variable_set(:@declared_at, declared_at)
      injection.freeze
    end

    def self.nothing
      NOTHING
    end

    def self.do_not_inherit
      DO_NOT_INHERIT
    end

    def empty?
      explicit.empty? && defaults.empty?
    end

    def clear
      explicit.clear
      defaults.clear
      self
    end

    def ==(other)
      other.is_a?(DependencyInjection) && explicit == other.explicit && defaults == other.defaults
    end
    alias eql? ==

    def hash
      [explicit, defaults].hash
    end

    # Adds selections (Syskit's +add+): hashes of key => value (later keys
    # override earlier ones; selecting a model for itself keeps what it
    # selects), values without a key (defaults), other DependencyInjection
    # objects. Changes and returns self.
    def add(*mappings)
      add_located(mappings, Location.of_caller)
    end

    # Makes +keys+ (child names) select nothing by name here, so that what
    # an enclosing layer selected for them by name does not apply.
    def add_mask(keys)
      keys.each { |key| explicit[key] = DO_NOT_INHERIT }
      self
    end

    # Adds +mappings+ (see #add), normalized, to the explicit selections.
    def add_explicit(mappings)
      mappings.each do |key, value|
        value.freeze if value.is_a?(InstanceRequirements) # held by the injection from now on, as in Syskit
        explicit[key] = value unless value == key && explicit.key?(key)
      end
      @explicit = DependencyInjection.resolve_recursive_selection_mapping(explicit)
      self
    end

    def add_defaults(values)
      values.each { |value| value.freeze if value.is_a?(InstanceRequirements) }
      @defaults |= values
      self
    end

    # The selection of +key+ (a name or model), defaults resolved; nil when
    # nothing or do_not_inherit is selected.
    def direct_selection_for(key)
      value = resolve.explicit[key]
      value unless DependencyInjection.placeholder?(value)
    end

    # A copy whose defaults are resolved into explicit selections (see
    # .resolve_default_selections), chains followed.
    def resolve
      return self if defaults.empty?

      DependencyInjection.new(DependencyInjection.resolve_recursive_selection_mapping(
                                DependencyInjection.resolve_default_selections(explicit, defaults)
                              ))
    end

    # Replaces the selections given by name with what +mapping+ (a table
    # of selections) selects for that name (see .find_name_resolution);
    # returns the names left unresolved.
    def resolve_names(mapping = {})
      unresolved = Set.new
      map! do |value|
        next value unless value.is_a?(String)

        resolved = DependencyInjection.find_name_resolution(value, mapping)
        unresolved << value unless resolved
        resolved || value
      end
      unresolved
    end

    # Replaces each selected value (explicit and default) with what the
    # block returns for it.
    def map!(&)
      @explicit = DependencyInjection.resolve_recursive_selection_mapping(explicit.transform_values(&))
      @defaults = defaults.to_set(&)
      self
    end

    # Enumerates the selected values.
    def each(&block)
      return enum_for(__method__) unless block

      explicit.each_value(&block)
      defaults.each(&block)
      self
    end

    # Selections of the children of child +name+, from the keys
    # 'name.grandchild' (by grandchild name).
    def grandchild_selections(name)
      prefix = "#{name}."
      explicit.each_with_object({}) do |(key, value), result|
        result[key.delete_prefix(prefix)] = value if key.is_a?(String) && key.start_with?(prefix)
      end
    end

    # What the selections named that this gem does not model, left out of
    # them, the selected requirements' included: pairs of what it is and
    # where it was selected. A profile's definition that depends on one is
    # left out of the plan (see Actions::ProfileDefinitions#define).
    def not_modelled
      nested = explicit.each_value.grep(InstanceRequirements).flat_map { |r| r.selections.not_modelled }
      [*@not_modelled, *nested].uniq
    end

    def to_s
      parts = explicit.map { |k, v| "#{key_name(k)} => #{v}" } + defaults.map(&:to_s)
      "use(#{parts.join(', ')})"
    end
    alias inspect to_s

    def pretty_print(pp)
      pp.text(to_s)
    end

    private

    def add_located(mappings, location)
      explicit = {}
      defaults = []
      mappings.each do |mapping|
        next if not_modelled?(mapping, location)

        case mapping
        when Hash
          mapping.each { |k, v| explicit[k] = v unless not_modelled?(k, location) || not_modelled?(v, location) }
        when DependencyInjection
          @not_modelled = [*@not_modelled, *mapping.not_modelled].uniq.freeze
          explicit = mapping.explicit.merge(explicit)
          defaults.concat(mapping.defaults.to_a)
        else defaults << DependencyInjection.normalize_selected_object(mapping, nil, location)
        end
      end
      add_explicit(DependencyInjection.normalize_selection(explicit, location))
      add_defaults(defaults)
      @declared_at = location
      self
    end

    # A value made by a statement this gem does not model (the device
    # use_gazebo_model makes from an SDF file): the selection is left out,
    # and remembered (see #not_modelled).
    def not_modelled?(value, location)
      return false unless Compat::Ignored === value # rubocop:disable Style/CaseEquality

      @not_modelled = [*@not_modelled, [value.to_s, location]].freeze
      true
    end

    def key_name(key)
      key.is_a?(String) ? "'#{key}'" : key.to_s
    end
  end
end
