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
      def to_s
        name || super
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
