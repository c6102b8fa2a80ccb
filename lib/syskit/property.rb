# frozen_string_literal: true

module Syskit
  # One property of a task (+task.property('period')+, +task.period_property+):
  # its name, its type and the value configure methods and configuration
  # sections give it. Values are converted to the property's type as they
  # are written; what a running component does with them is not modelled.
  class Property
    # The current value, converted to the property's type.
    attr_reader :value

    # +declaration+: the property as +task_model+ declares it
    # (Orogen::Property), which gives its name, type and initial value;
    # +task_context+ is nil for properties of no task.
    def initialize(declaration, task_model, task_context = nil)
      @declaration = declaration
      @owner = task_context || task_model
      @value = declaration.initial_value
    end

    def name
      @declaration.name
    end

    def type
      @declaration.type
    end

    # The task it is a property of (nil for the properties a configuration
    # section is checked on, which belong to no task).
    def task_context
      @owner unless @owner.is_a?(Module)
    end

    def read
      value
    end

    # Sets the value, converting +value+ to the property's type; raises a
    # ConfigurationError pointing at the caller when it does not fit. A
    # value made from something this gem does not model (the SDF model of
    # a simulated robot) leaves the value as it is, with a warning.
    def write(value)
      if Compat::Ignored === value # rubocop:disable Style/CaseEquality
        Syskit.app&.not_modelled("property '#{name}' of #{owner_name} set from something not modelled " \
                                 '(it keeps its value)', Location.of_caller)
      else
        @value = type.from_ruby(value)
      end
      value
    rescue Types::ValueError, ArgumentError => e
      raise ConfigurationError.new("property '#{name}' of #{owner_name}: #{e.message}",
                                   location: Location.of_caller, hint: "give it a value of type #{type}")
    end

    # Syskit reads and writes a component's values as typed (Typelib)
    # values through these; here values are always of the property's type.
    alias raw_read read
    alias raw_write write

    # The value as plain data (hashes, arrays, numbers, strings).
    def to_plain
      type.to_plain(value)
    end

    def to_s
      "property '#{name}' of #{owner_name}"
    end
    alias inspect to_s

    private

    def owner_name
      @owner.is_a?(Module) ? @owner.name : @owner.model.name
    end
  end
end
