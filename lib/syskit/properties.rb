# frozen_string_literal: true

module Syskit
  # The +properties+ of a task: one reader and writer per property of its
  # model, checking values against the property's type.
  class Properties
    # The properties class of +task_model+, with a reader and a writer per
    # property. A property named like a method of this class (names, to_h,
    # ...) keeps the method; it is read and written with properties['name'].
    def self.for(task_model)
      klass = Class.new(self)
      klass.instance_variable_set(:@task_model, task_model)
      task_model.property_declarations.each_key do |name|
        next if method_defined?(name) || private_method_defined?(name)

        klass.define_method(name) { self[name] }
        klass.define_method("#{name}=") { |value| self[name] = value }
      end
      klass
    end

    class << self
      attr_reader :task_model

      def sorted_names
        @sorted_names ||= task_model.property_declarations.keys.sort.freeze
      end
    end

    def initialize
      @values = self.class.task_model.property_declarations.transform_values(&:initial_value)
    end

    def declarations
      self.class.task_model.property_declarations
    end

    def [](name)
      @values.fetch(check_name(name))
    end

    # Sets a property, converting +value+ to its type; raises a
    # ConfigurationError pointing at the caller when it does not fit.
    def []=(name, value)
      name = check_name(name)
      if Compat::Ignored === value # rubocop:disable Style/CaseEquality
        not_modelled_value(name)
      else
        @values[name] = declarations.fetch(name).type.from_ruby(value)
      end
    rescue Types::ValueError, ArgumentError => e
      raise ConfigurationError.new(
        "property '#{name}' of #{self.class.task_model.name}: #{e.message}",
        location: Location.of_caller, hint: "give it a value of type #{declarations[name]&.type}"
      )
    end

    # A value made from something this gem does not model (the SDF model
    # of a simulated robot): the property keeps its value, with a warning.
    def not_modelled_value(name)
      Syskit.app&.not_modelled("property '#{name}' of #{self.class.task_model.name} set from something not " \
                               'modelled (it keeps its value)', Location.of_caller)
      @values[name]
    end

    def key?(name)
      @values.key?(name.to_s)
    end

    # Why properties.+name+ does not exist, for typos in configure methods.
    def explain_missing(name)
      name = name.delete_suffix('=')
      ["#{self.class.task_model.name} has no property '#{name}'#{Naming.did_you_mean(name, names)}",
       "its properties are #{names.sort.join(', ').then { |s| s.empty? ? '(none)' : s }}"]
    end

    def names
      @values.keys
    end

    # Values as plain data (hashes, arrays, numbers, strings), sorted by name.
    def to_plain
      plain = {}
      self.class.sorted_names.each { |k| plain[k] = declarations[k].type.to_plain(@values[k]) }
      plain
    end

    def to_h
      @values.dup
    end

    private

    def check_name(name)
      name = name.to_s
      return name if @values.key?(name)

      raise ConfigurationError.new(
        "#{self.class.task_model.name} has no property '#{name}'#{Naming.did_you_mean(name, @values.keys)}",
        location: Location.of_caller,
        hint: "its properties are #{@values.keys.sort.join(', ').then { |s| s.empty? ? '(none)' : s }}"
      )
    end
  end
end
