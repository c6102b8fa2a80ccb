# frozen_string_literal: true

require 'syskit/models/component'
require 'syskit/models/component_submodels'

module Syskit
  # The root of the components of a network, as in Syskit: task contexts
  # and compositions are Components. Models (the subclasses) are extended
  # with Models::Component.
  class AbstractComponent
    extend Models::Component
    extend Models::ComponentSubmodels
  end

  # What task contexts and compositions are (Syskit::Component): the
  # class test files and custom models name.
  class Component < AbstractComponent
    class << self
      # A component model made in Ruby (+Syskit::Component.new_submodel+,
      # or +model.new_submodel+ for one of its submodels), named +name+
      # until a constant names it; the block is its class body.
      def new_submodel(name: nil, &block)
        model = Class.new(self)
        model.instance_variable_set(:@given_name, name) if name
        model.instance_variable_set(:@declared_at, Location.of_caller)
        Models.register_model(model)
        model.class_eval(&block) if block
        model
      end

      def name
        super || @given_name
      end

      # Where it was made (see .new_submodel).
      attr_reader :declared_at

      def to_s
        name || "anonymous component (#{declared_at})"
      end

      # The name shown to users.
      def short_name
        to_s
      end
    end

    # Syskit's name for Models::Placeholder.for: a model standing for any
    # component providing +models+.
    def self.create_proxy_task_model(models, **)
      Models::Placeholder.for(models)
    end

    private

    # Sets the task's arguments as Roby does: a declared argument through
    # its writer (+argument :x+ gives one; a model may define its own, that
    # checks or derives values: +def setpoint=(hash) ...
    # arguments[:setpoint] = hash end+), the others, and a delayed
    # argument, as they are.
    def assign_arguments(given)
      @arguments = {}
      given.each do |key, value|
        if model.argument_declared?(key) && !value.is_a?(Compat::DelayedArgument)
          public_send(:"#{key}=", value)
        else
          @arguments[key] = value
        end
      end
    end
  end
end
