# frozen_string_literal: true

require 'syskit/models/fullfillment'
require 'syskit/network_generation/port_dynamics'
require 'syskit/instance_requirements/statements'
require 'syskit/instance_requirements/readers'
require 'syskit/instance_requirements/combination'
require 'syskit/instance_requirements/changes'
require 'syskit/actions/models/action'
require 'syskit/instance_requirements_task'
require 'syskit/models/faceted_access'

module Syskit
  # What a network must contain, as Syskit's InstanceRequirements: a model
  # (a task or composition model, or services to be provided by a component
  # chosen later), or a device of the robot (its driver), with what is
  # asked of it:
  #
  #   Compositions::ArmControl.use('arm' => Base.arm_dev).with_arguments(speed: 0.1)
  #   OroGen.gps.Task.with_conf('default', 'rtk').prefer_deployed_tasks(/gps/)
  #   Base.gps_dev                       # a device's driver
  #
  # As Syskit's, requirements change: a statement changes the requirements
  # it is called on and returns them, their deployment hints and group are
  # theirs to add to, and +dup+ gives a copy to change. Frozen ones (what
  # models, profiles and injections hold) give a changed copy instead (see
  # Changes). A profile's definitions and device actions are requirements
  # with a +name+.
  class InstanceRequirements
    include Statements
    include Readers
    include Combination
    include Changes
    # Whether these requirements fullfill a model (or each of a list).
    include Models::Fullfillment

    NO_ARGUMENTS = {}.freeze
    NO_HINTS = [].freeze
    NO_PORT_DYNAMICS = {}.freeze
    DEFAULT_CONF = ['default'].freeze
    FIELDS = %i[models device service profile name arguments conf conf_location deployment_hints deployment
                deployment_group selections specialization_hints declared_at instance abstract doc port_dynamics].freeze

    # +instance+: a task of the network being generated, when these
    # requirements select it (a composition's child given to another);
    # +conf_location+: where the sections were chosen (with_conf);
    # +port_dynamics+: what add_port_period said, by port name.
    attr_reader :device, :service, :profile, :name, :deployment, :selections,
                :specialization_hints, :declared_at, :instance, :conf_location, :doc, :port_dynamics

    # What stands for requirements besides models and lists of them (see
    # .from): requirements, a model's service, a device, a tag, a
    # composition's child, a task of the network being generated.
    def self.selectable_kinds
      [InstanceRequirements, Models::DataServiceModel, Robot::MasterDeviceInstance, Models::BoundDataService,
       Models::ChildReference, Actions::Profile::Tag, AbstractComponent, Syskit::BoundDataService]
    end

    # Whether +value+ can stand for a component in a network (what +use+
    # and +add+ accept).
    def self.selectable?(value)
      # What a not-modelled statement returned answers any call: asked first.
      return false if Compat::Ignored === value # rubocop:disable Style/CaseEquality
      return value.all? { |v| selectable?(v) } if value.is_a?(Array) && !value.empty?

      (value.is_a?(Class) && value < AbstractComponent) || selectable_kinds.any? { |kind| value.is_a?(kind) }
    end

    # The requirements +value+ stands for (see .selectable?).
    def self.from(value, location: nil)
      case value
      when InstanceRequirements then value
      when Actions::Profile::Tag, Models::ChildReference then value.requirements
      when Robot::MasterDeviceInstance then new(device: value, declared_at: value.declared_at)
      when Models::BoundDataService then new([value.task_model], service: value, declared_at: location)
      when AbstractComponent then new([value.model], instance: value, declared_at: location)
      when Syskit::BoundDataService
        new([value.component.model], service: value.model, instance: value.component, declared_at: location)
      when Array then new(value.map { |v| from(v, location: location).models }.flatten.uniq, declared_at: location)
      else new([value], declared_at: location)
      end
    end

    # +models+ with the component model's service +bound+ replaced by its
    # component model: a service among the models stands for its component
    # model with that service selected, as in Syskit.
    def self.without_service(models, bound)
      return models&.freeze unless bound

      models.map { |m| m.equal?(bound) ? bound.component_model : m }.freeze
    end

    # The models +value+ (a selection) fullfills: what a default selection
    # is registered under.
    def self.fullfilled_models_of(value)
      from(value).fullfilled_models
    end

    def initialize(models = nil, device: nil, service: nil, profile: nil, name: nil, arguments: NO_ARGUMENTS,
                   conf: nil, conf_location: nil, deployment_hints: nil, deployment: nil, deployment_group: nil,
                   selections: DependencyInjection::EMPTY, specialization_hints: NO_HINTS, declared_at: nil,
                   instance: nil, abstract: false, doc: nil, open: false, port_dynamics: NO_PORT_DYNAMICS)
      bound = models&.grep(Models::BoundDataService)&.first
      @models = InstanceRequirements.without_service(models, bound)
      @device = device
      @service = service || bound
      @profile = profile
      @name = name
      @arguments = arguments.frozen? ? arguments : arguments.dup.freeze
      @conf = conf&.freeze
      @conf_location = conf_location
      @deployment_hints = InstanceRequirements.own_hints(deployment_hints, open)
      @deployment = deployment
      # A group still open to changes is another's: these get their own.
      @deployment_group = deployment_group&.frozen? ? deployment_group : deployment_group&.dup
      @selections = selections
      @specialization_hints = specialization_hints
      @declared_at = declared_at
      @instance = instance
      @abstract = abstract
      @doc = doc
      @port_dynamics = port_dynamics
      @open = open
      # Held, as frozen ones (see Changes#held?): their lists are too.
      freeze_deployments if open
      extend_readers
    end

    # A new requirements' list of hints, a copy of +given+: held ones
    # (+open+, see #initialize) freeze it, so without hints given they
    # share the frozen empty one (a profile's device actions).
    def self.own_hints(given, open)
      return given.dup if given

      open ? NO_HINTS : []
    end

    # The required models: a component model and/or data service models;
    # a device's model for a device.
    def models
      @models || (device ? [device.model] : [])
    end

    # What the requirements are (Syskit's +model+, and +base_model+): the
    # selected service; for a device's, its driver's service once the
    # driver is known, as Syskit's device requirements are the driver's;
    # else the proxy model.
    def model
      service || device_driver_service || proxy_model
    end
    alias base_model model

    # The task arguments; a master device's own requirements also bind its
    # driver's service to the device (+gps_dev: device+), as Syskit's.
    def arguments
      return @arguments unless device_driver_service
      return device.driver_arguments if @arguments.empty?

      device.driver_arguments.merge(@arguments)
    end

    # The service that drives the device of these requirements, when they
    # are a master device's own (no model given) and its driver is known.
    def device_driver_service
      device.driver_model if device && @models.nil? && !device.master_device && device.driver_resolved?
    end

    # The component model, or the placeholder standing for it and the
    # required services it does not provide.
    def proxy_model
      component = component_model
      return component if component && models.all? { |m| component.fullfills?(m) }

      Models::Placeholder.for(models)
    end

    # Equal when they ask for the same thing (where they are written aside).
    def ==(other)
      other.is_a?(InstanceRequirements) && other.compared == compared
    end
    alias eql? ==

    def hash
      compared.hash
    end

    # The task or composition model among the models (nil when only
    # services are required: the requirements are then abstract).
    #
    # Asked several times per task while generating, so it allocates
    # nothing: a device's requirements (no models given) require its
    # device model, a module; Array#index, unlike Enumerable#find, makes
    # no intermediate objects.
    def component_model
      return if @models.nil?

      found = @models.index { |m| m.is_a?(Class) }
      @models[found] if found
    end

    def composition?
      component_model.is_a?(Class) && component_model <= Composition
    end

    # Whether something must still be chosen to fill these requirements:
    # when marked so (#abstract), or when they require services only or
    # an abstract model.
    def abstract?
      return true if @abstract
      return false if device || instance

      model = component_model
      model.nil? || model.abstract?
    end

    # Configuration sections; a device's own, or ['default'].
    def conf
      @conf || device&.conf || DEFAULT_CONF
    end

    # Whether sections were chosen on these requirements (not inherited).
    def conf_given?
      !@conf.nil?
    end

    # The deployed tasks to prefer (see #prefer_deployed_tasks), a list
    # to add to (Syskit's tests append to it), frozen when the requirements
    # are held; without hints of their own, the device's (frozen).
    def deployment_hints
      own = @deployment_hints
      return own unless own.empty?

      hints = device&.deployment_hints
      return own if hints.nil? || hints.empty?

      hints.frozen? ? hints : hints.dup.freeze
    end

    # Where the deployment hints were given, for errors about them.
    def deployment_hints_location
      (@deployment_hints.empty? ? device&.deployment_hints_location : declared_at) || declared_at
    end

    # The deployment given with deployed_as (a device's own when it has one).
    def declared_deployment
      deployment || device&.declared_deployment
    end

    # The deployed tasks these requirements' network may use before the
    # robot's (Syskit's deployment group, see #use_deployment): their own,
    # to add deployments to, frozen when the requirements are held.
    def deployment_group
      group = @deployment_group
      return group || Models::DeploymentGroup.empty if held?
      return group if group && !group.frozen?

      @deployment_group = group ? group.dup : Models::DeploymentGroup.new
    end

    # Each required model, then what they provide.
    def fullfilled_models
      list = []
      models.each { |m| m.each_fullfilled_model { |f| list << f unless list.include?(f) } }
      if device&.driver_resolved?
        device.driver_model.component_model.each_fullfilled_model { |f| list << f unless list.include?(f) }
      end
      list
    end

    def each_fullfilled_model(&)
      fullfilled_models.each(&)
    end

    def each_required_model(&)
      models.each(&)
    end

    # The composition model these requirements select once injection and
    # specializations apply (Syskit's +narrow_model+).
    def narrow_model
      return component_model unless composition?

      context = profile ? profile.dependency_injection_context : DependencyInjectionContext::EMPTY
      component_model.narrow(context.with(selections), hints: specialization_hints)
    end

    def to_instance_requirements
      self
    end

    # These requirements seen through +models+ (models they fullfill), a
    # Models::FacetedAccess. With a service selected, Syskit selects the
    # component model's service of that name: the same requirements, once
    # the service is checked to provide +models+.
    def as(models)
      if service
        service.as(models)
        return copy(service: component_model&.find_service(service.full_name) || service)
      end

      Models::FacetedAccess.new(self, Models::Placeholder.for(Array(models)))
    end

    # Syskit's +instanciate+: the task these requirements stand for, its
    # children selected in +context+ (a DependencyInjectionContext), added
    # to +plan+ with them (see Network::Instantiate.into_plan); with a
    # service selected, that service of the task (a Syskit::BoundDataService,
    # as Syskit's). +task_arguments+ are the root task's arguments (+conf:+
    # its sections); +specialization_hints+ the specializations to prefer.
    def instanciate(plan, context = DependencyInjectionContext::EMPTY, task_arguments: {}, specialization_hints: [])
      arguments = task_arguments.dup
      conf = Array(arguments.delete(:conf))
      requirements = dup.with_arguments(**arguments)
      requirements = requirements.with_conf(*conf) unless conf.empty?
      requirements = requirements.prefer_specializations(specialization_hints) unless specialization_hints.empty?
      task = Network::Instantiate.into_plan(plan, requirements, context)
      service ? service.bind(task) : task
    end

    # An action by its name (+Base.drive_def+, +gps_dev+), else the model
    # and the statements that changed it, as they are written.
    def to_s
      return "#{action_name}#{".#{service.name}_srv" if service}" if name
      return "#{device.name}_dev" if device

      parts = [base_name]
      parts << selections.to_s unless selections.empty?
      parts << "with_conf(#{conf.map(&:inspect).join(', ')})" if @conf
      parts << "with_arguments(#{arguments.map { |k, v| "#{k}: #{v.inspect}" }.join(', ')})" unless arguments.empty?
      parts.join('.')
    end
    alias inspect to_s
    alias short_name to_s

    protected

    # An empty group is no group, whether the requirements made theirs yet.
    def compared
      (FIELDS - %i[declared_at conf_location doc]).map do |f|
        value = instance_variable_get(:"@#{f}")
        f == :deployment_group && value&.empty? ? nil : value
      end
    end

    # A definition's or a device's action, by the name of its profile.
    def action_name
      profile ? "#{profile.name}.#{name}" : name
    end

    def base_name
      return "#{service.task_model.name}.#{service.name}_srv" if service

      models.map { |m| m.respond_to?(:short_name) ? m.short_name : m.to_s }.join(',')
    end
  end
end
