# frozen_string_literal: true

module Syskit
  # The properties of a task context instance as Syskit's TaskContext
  # gives them: +task.property('period')+ (a Property),
  # +task.period_property+, +task.has_property?+, +task.each_property+,
  # and +task.properties+ (see Properties).
  module TaskProperties
    attr_reader :properties

    # The property called +name+ (a string or a symbol); raises
    # Orocos::InterfaceObjectNotFound, as Syskit does, when there is none.
    def property(name)
      found = find_property(name)
      return found if found

      raise Compat::Orocos::InterfaceObjectNotFound,
            "#{model.name} has no property '#{name}'#{Naming.did_you_mean(name.to_s, properties.names)}"
    end

    # The property called +name+, nil when there is none.
    def find_property(name)
      properties[name]
    end

    def has_property?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
      properties.include?(name)
    end

    # Enumerates its Property objects.
    def each_property(&)
      properties.each(&)
    end
  end
end
