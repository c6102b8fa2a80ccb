# frozen_string_literal: true

require 'syskit/models/component'

module Syskit
  # The root of the components of a network, as in Syskit: task contexts
  # and compositions are Components. Models (the subclasses) are extended
  # with Models::Component.
  class AbstractComponent
    extend Models::Component

    # The compositions this task is a child of (Roby's +each_parent_task+).
    def each_parent_task(&)
      return enum_for(__method__) unless block_given?

      (@parent_tasks || []).each(&)
    end

    # Records +composition+ as a parent (see Composition#add_child).
    def add_parent_task(composition)
      (@parent_tasks ||= []) << composition unless @parent_tasks&.any? { |p| p.equal?(composition) }
    end

    def remove_parent_task(composition)
      @parent_tasks&.delete_if { |p| p.equal?(composition) }
    end
  end

  # What task contexts and compositions are (Syskit::Component): the
  # class test files and custom models name.
  class Component < AbstractComponent
    # A component model made in Ruby that is neither a task context nor a
    # composition (+Syskit::Component.new_submodel { provides Srv, as: 's' }+),
    # as Syskit's tests make them: services and arguments, no ports.
    def self.new_submodel(name: nil, &block)
      model = Class.new(self)
      model.instance_variable_set(:@given_name, name) if name
      model.class_eval(&block) if block
      model
    end

    # The name given to new_submodel, else the constant's.
    def self.name
      super || @given_name
    end

    def self.to_s
      name || 'anonymous component'
    end

    def self.short_name
      to_s
    end

    def self.inspect
      to_s
    end

    # Marked abstract by +abstract+ only (see Models::TaskContext).
    def self.abstract?
      false
    end

    # A component model has no ports of its own (task contexts and
    # compositions do).
    def self.ports
      {}
    end

    def self.find_port(_name); end

    # Nor does it drive devices (task contexts may).
    def self.driver_services
      []
    end

    # What Instantiate sets on the tasks it makes (see TaskContext).
    attr_reader :arguments
    attr_accessor :conf, :requirement, :plan_path, :root_location

    def initialize(arguments = {})
      super()
      @conf = InstanceRequirements::DEFAULT_CONF
      assign_arguments(arguments)
    end

    def model
      self.class
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
