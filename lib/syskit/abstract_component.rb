# frozen_string_literal: true

require 'syskit/models/component'
require 'syskit/compat/roby_task_arguments'
require 'syskit/compat/roby_plan_service'
require 'syskit/models/component_submodels'
require 'syskit/models/task_specialization'
require 'syskit/component_merging'
require 'syskit/dynamic_port_binding'

module Syskit
  # The root of the components of a network, as in Syskit: task contexts
  # and compositions are Components. Models (the subclasses) are extended
  # with Models::Component.
  class AbstractComponent
    extend Models::Component
    extend Models::ComponentSubmodels
    extend Models::TaskSpecialization

    # Its model: its class, or the private specialization #specialize
    # made for this task alone.
    def model
      @model || self.class
    end

    # Gives the task a model of its own (a specialization of its model),
    # which can then provide services its model does not. True if it made
    # one, false if the task's model already is private to it.
    def specialize
      return false if @model

      @model = model.specialize
      @bound_services = nil
      true
    end

    # The model the task's model was specialized from (its model if it is
    # no specialization): what deployments and users know it by.
    def concrete_model
      model.concrete_model
    end

    # Whether the task's model is a specialization (#specialize, on the
    # task or on its model).
    def specialized_model?
      !concrete_model.equal?(model)
    end

    # The models the task stands for: its concrete model, never the
    # specialization made for it.
    def provided_models
      [concrete_model]
    end

    # Roby's pair of the models and the arguments the task is known to
    # fullfill: its provided models and the arguments it has set (not the
    # default ones).
    def fullfilled_model
      [provided_models, arguments.each_assigned_argument.to_h]
    end

    # Whether its model fullfills +models+ (a model or a list).
    def fullfills?(models)
      model.fullfills?(models)
    end

    # The service +name+ of this component (+task.gps_srv+ reads it): its
    # model's service, bound to this component, one object per service.
    def find_data_service(name)
      name = name.to_s
      bound = (@bound_services ||= {})
      return bound[name] if bound.key?(name)

      srv = model.find_data_service(name)
      bound[name] = srv && BoundDataService.new(self, srv)
    end

    # Its services whose model is or provides +srv_model+, each seen as
    # +srv_model+ (what +Srv.try_bind(task)+ chooses from).
    def find_all_data_services_from_type(srv_model)
      model.find_all_data_services_from_type(srv_model).map do |srv|
        find_data_service(srv.full_name).as(srv_model)
      end
    end

    # The only service of type +srv_model+, nil if none, an
    # AmbiguousServiceSelection if several.
    def find_data_service_from_type(srv_model)
      candidates = find_all_data_services_from_type(srv_model)
      return candidates.first if candidates.size <= 1

      raise AmbiguousServiceSelection.new(
        "#{self} has several services of type #{srv_model}: #{candidates.map(&:full_name).sort.join(', ')}",
        location: Location.of_caller, hint: 'choose one by its name (task.name_srv)'
      )
    end

    # Roby's +task.as_service+: a handle on this task that follows its
    # replacements (see Compat::Roby::PlanService).
    def as_service
      self.plan_service ||= Compat::Roby::PlanService.new(self)
    end

    # The plan service of this task, once #as_service made one.
    attr_accessor :plan_service

    # The task itself (what a plan service or a bound service gives too).
    def to_task
      self
    end

    # The services its model requires of dynamic services, bound to this
    # task (see Models::DynamicServices#require_dynamic_service). Without
    # a block, the list (Syskit's tests ask it +empty?+).
    def each_required_dynamic_service(&block)
      return enum_for(__method__).to_a unless block

      model.required_dynamic_services.each { |srv| yield srv.bind(self) }
    end

    # The compositions this task is a child of (Roby's +each_parent_task+),
    # in the order they became its parents.
    def each_parent_task(&)
      return enum_for(__method__) unless block_given?

      @parent_tasks&.each_key(&)
    end

    # Records +composition+ as a parent (see Composition#add_child). Kept
    # by identity in a hash: a task all compositions share (merged into
    # one) has as many parents as there are compositions.
    def add_parent_task(composition)
      (@parent_tasks ||= {}.compare_by_identity)[composition] = true
    end

    def remove_parent_task(composition)
      @parent_tasks&.delete(composition)
    end
  end

  # What task contexts and compositions are (Syskit::Component): the
  # class test files and custom models name.
  class Component < AbstractComponent
    include ComponentMerging
    include DynamicPortBinding::ComponentAccessors

    class << self
      # Where it was made (see Models::Component#new_submodel).
      attr_reader :declared_at

      def to_s
        name || super
      end

      # The name shown to users.
      def short_name
        to_s
      end

      def inspect
        to_s
      end

      # A plain component model has no ports (task contexts and
      # compositions do). (It drives no device: it has no driver service,
      # see Models::DriverServices.)
      def ports
        {}
      end

      def find_port(_name); end

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

    attr_reader :arguments
    # The requirements (a device action, a composition's child, what
    # InstanceRequirements#instanciate was given) the task was made for
    # (Syskit's +requirements+); see #requirements.
    attr_writer :requirements
    # Where it stands in the network; where the requirements of the
    # network's root it belongs to are declared (the definition).
    attr_accessor :plan_path, :root_location

    # Its configuration sections (+task.conf+), an argument as in Syskit:
    # +new(conf: %w[default slow])+ or +task.conf = [...]+ set it.
    argument :conf, default: %w[default].freeze

    # The arguments of a task made without any (shared, never changed).
    NO_ARGUMENTS = {}.freeze

    # What plans it, when it stands for requirements still to be planned
    # (see InstanceRequirements#as_plan).
    attr_accessor :planning_task

    # Subclasses set up their own state first, then call super with the
    # arguments, so that they are assigned once.
    def initialize(arguments = NO_ARGUMENTS)
      super()
      assign_arguments(arguments)
    end

    # Syskit's name for Models::Placeholder.for: a model standing for any
    # component providing +models+.
    def self.create_proxy_task_model(models, component_model: nil, as: nil)
      Models::Placeholder.for(models, component_model: component_model, as: as)
    end

    # The requirements the task was made for; a task made alone
    # (+Model.new+) has empty ones, as in Syskit, to which its deployment
    # hints can be added (see #deployment_hints).
    def requirements
      @requirements ||= InstanceRequirements.new
    end

    # The hints choosing its deployed task (see prefer_deployed_tasks): its
    # requirements', else those of the compositions it is a child of, as
    # Syskit merges them.
    def deployment_hints
      own = requirements.deployment_hints
      return own unless own.empty?

      each_parent_task.flat_map(&:deployment_hints).uniq
    end

    # Requirements that would give a task like this one: its model, with
    # the arguments it has set (not the delayed or default ones).
    def to_instance_requirements
      set = arguments.each_assigned_argument.to_h
      requirements = model.to_instance_requirements
      requirements = requirements.with_conf(*set.delete(:conf)) if set.key?(:conf)
      requirements.with_arguments(**set)
    end

    # Whether the task stands for a component (see Syskit::Placeholder).
    def placeholder?
      false
    end

    # Whether the task is of an abstract model (a placeholder's, an
    # abstract task's), or was made for requirements marked abstract:
    # something must still be chosen in its place, a network cannot run it.
    def abstract?
      return @abstract unless @abstract.nil?

      return true if model.abstract?

      # The requirements of a task made alone require nothing: they do not
      # make it abstract.
      requirements = @requirements
      requirements && !requirements.models.empty? ? requirements.abstract? : false
    end

    # Marks the task abstract (or not), whatever its model and
    # requirements say, as Roby's +task.abstract = true+.
    attr_writer :abstract

    # The services of this task, as Syskit::BoundDataService.
    def each_data_service(&block)
      return enum_for(__method__) unless block

      model.services.each_key { |name| yield find_data_service(name) }
    end

    private

    # Sets the task's arguments as Roby does: a declared argument through
    # its writer (+argument :x+ gives one; a model may define its own, that
    # checks or derives values: +def setpoint=(hash) ...
    # arguments[:setpoint] = hash end+), the others, and a delayed
    # argument, as they are.
    def assign_arguments(given)
      @arguments = Compat::Roby::TaskArguments.new.merge!(model.default_arguments)
      given.each do |key, value|
        if model.argument_declared?(key) && !value.is_a?(Compat::DelayedArgument) &&
           !value.is_a?(Compat::Roby::DefaultArgument)
          public_send(:"#{key}=", value)
        else
          @arguments[key] = value
        end
      end
    end
  end
end
