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

    def model
      self.class
    end

    # The service +name+ of this component (+task.gps_srv+ reads it): its
    # model's service, bound to this component.
    def find_data_service(name)
      srv = model.find_data_service(name)
      srv && BoundDataService.new(self, srv)
    end
  end

  # What task contexts and compositions are (Syskit::Component): the
  # class test files and custom models name.
  class Component < AbstractComponent
    class << self
      # Where it was made (see Models::Component#new_submodel).
      attr_reader :declared_at

      def to_s
        name || "anonymous component (#{declared_at})"
      end

      # The name shown to users.
      def short_name
        to_s
      end

      private

      # A plain component model (+Syskit::Component.new_submodel+): made
      # where the caller is, and removed after the test that made it.
      def submodel_class
        model = Class.new(self)
        model.instance_variable_set(:@declared_at, Location.of_caller)
        Models.register_model(model)
        model
      end
    end

    # Syskit's name for Models::Placeholder.for: a model standing for any
    # component providing +models+.
    def self.create_proxy_task_model(models, component_model: nil, as: nil)
      Models::Placeholder.for(models, component_model: component_model, as: as)
    end

    # Whether the task stands for a component (see Syskit::Placeholder).
    def placeholder?
      false
    end

    # Whether the task is of an abstract model (a placeholder's, an
    # abstract task's): a network cannot run it.
    def abstract?
      model.abstract? || false
    end

    # The service +name+ of this task (a Syskit::BoundDataService), or nil.
    def find_data_service(name)
      srv = model.find_service(name.to_s)
      srv && BoundDataService.new(self, srv)
    end

    # The services of this task, as Syskit::BoundDataService.
    def each_data_service(&block)
      return enum_for(__method__) unless block

      model.services.each_value { |srv| yield BoundDataService.new(self, srv) }
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
