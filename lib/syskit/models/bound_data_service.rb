# frozen_string_literal: true

require 'syskit/models/bound_data_service_ports'
require 'syskit/models/task_requirements'

module Syskit
  module Models
    # A service provided by a task model, from +provides+ or +driver_for+:
    # its name (+as:+), the service model and which task port each service
    # port is. A service declared +slave_of:+ another has that service as
    # its +master+ and is named after it (+stereo.left+). Its ports and
    # lookups (+Task.gps_srv.pose_port+) are in BoundDataServicePorts.
    class BoundDataService
      include BoundDataServicePorts
      include TaskRequirementStatements

      NO_OPTIONS = {}.freeze
      private_constant :NO_OPTIONS

      attr_reader :task_model, :name, :model, :port_mappings, :declared_at, :master

      # The dynamic service this one is an instance of (nil for a service
      # the task model declares itself), and the options given for it
      # (+require_dynamic_service('export', as: 'x', joint_names: [...])+):
      # a configure method reads them (+srv.model.dynamic_service_options+).
      attr_reader :dynamic_service, :dynamic_service_options

      def initialize(task_model, name, model, port_mappings, location, master: nil,
                     dynamic_service: nil, dynamic_service_options: NO_OPTIONS, demoted: nil)
        @demoted = demoted
        @task_model = task_model
        @name = name
        @model = model
        @port_mappings = port_mappings.freeze
        @declared_at = location
        @master = master
        @dynamic_service = dynamic_service
        @dynamic_service_options = options_frozen(dynamic_service_options)
        define_port_readers
      end

      # Syskit's name for the task model the service belongs to.
      def component_model
        task_model
      end

      # A Queries::DataServiceMatcher finding this service on the tasks of
      # its task model.
      def match
        Queries::DataServiceMatcher.new(task_model.match).with_name(full_name).with_model(model)
      end

      # The models a task must fullfill to stand for the service, as
      # Syskit lists them: its service model.
      def fullfilled_model
        [model]
      end

      # Its service model and those it provides.
      def each_fullfilled_model(&)
        model.each_fullfilled_model(&)
      end

      # The name the task model knows the service by: +name+, after its
      # master's full name for a slave.
      def full_name
        @full_name ||= master ? "#{master.full_name}.#{name}" : name
      end

      # Whether it is a root service (not slave of another).
      def master?
        master.nil?
      end

      # Whether it is an instance of a dynamic service.
      def dynamic?
        !dynamic_service.nil?
      end

      # The device or bus model the task drives through this service, if any.
      def driven_device_model
        model.driven_device_model
      end

      # The task argument holding the device (+f9_dev+ for +as: 'f9'+).
      def argument_name
        @argument_name ||= :"#{name}_dev"
      end

      # Whether its service model is or provides +other+ (a service model,
      # a placeholder of service models alone, or a list of them); never a
      # component model.
      def fullfills?(other)
        return other.all? { |m| fullfills?(m) } if other.is_a?(Array)
        if other.respond_to?(:placeholder?) && other.placeholder?
          return other.proxied_component_model.equal?(Syskit::Component) &&
                 fullfills?(other.proxied_data_service_models)
        end

        model.fullfills?(other)
      end

      # The slave service +name+ of this service (+stereo_srv.find_data_service('left')+).
      def find_data_service(name)
        task_model.find_service("#{full_name}.#{name}")
      end

      # Enumerates this service's slaves, in declaration order.
      def each_slave_data_service(&block)
        return enum_for(__method__) unless block

        task_model.each_data_service { |srv| yield srv if srv.master&.full_name == full_name }
      end

      # The same service seen through +other+, a model it provides: its
      # ports are then +other+'s (+Task.bus_srv.as(Bus::ClientInSrv)+).
      def as(other)
        return self if other.equal?(model)

        unless fullfills?(other)
          raise DeclarationError.new("#{self} does not provide #{other}",
                                     location: Location.of_caller,
                                     hint: "its model provides #{model.each_fullfilled_model.to_a.join(', ')}")
        end

        self.class.new(task_model, name, other, port_mappings_for(other), declared_at,
                       master: master, dynamic_service: dynamic_service,
                       dynamic_service_options: dynamic_service_options, demoted: demoted)
      end

      # This service as a service of +component_model+, a submodel of its
      # task model (Syskit's promotion): what +Sub.gps_srv+ is when Sub
      # inherits the service; +master+ is the promoted master of a slave.
      # Given a service, attaches to that service's component model.
      def attach(component_model, master: nil)
        component_model = component_model.component_model if component_model.is_a?(BoundDataService)
        return self if component_model.equal?(task_model)

        unless component_model.is_a?(Class) && component_model < task_model
          raise DeclarationError.new("#{component_model.inspect} is not a submodel of #{task_model.name}",
                                     location: Location.of_caller,
                                     hint: "attach #{self} to a submodel of its task model")
        end

        self.class.new(component_model, name, model, port_mappings, declared_at,
                       master: master || self.master&.attach(component_model), dynamic_service: dynamic_service,
                       dynamic_service_options: dynamic_service_options, demoted: demoted)
      end

      # The service as its task model's first declaration made it (itself
      # unless it was promoted to a submodel, see #attach).
      def demoted
        @demoted || self
      end

      # Whether +other+ is this service, declared once and promoted to
      # submodels (whatever model it is seen through): both have the same
      # #demoted service.
      def same_service?(other)
        other.is_a?(BoundDataService) && other.demoted.equal?(demoted)
      end

      # This service of +task+ (a task of a network or of a test's plan),
      # as its configure method sees it (see Syskit::BoundDataService); given
      # a task's service, that service when it is this one. The task must
      # fullfill the service's component model: when it does without
      # deriving from it, the service is found on the task by name (a
      # placeholder's base model service, a dynamic service instance) or
      # by type (a service the placeholder stands for).
      def bind(task)
        return task if task.is_a?(Syskit::BoundDataService) && task.model == self
        return Syskit::BoundDataService.new(task, self) if task.model <= component_model

        unless task.fullfills?(component_model)
          raise ArgumentError, "cannot bind #{self} on #{task}: does not fullfill #{component_model}"
        end

        bind_by_name_or_type(task)
      end

      # The task port a port of +srv_model+ (this service's model or one it
      # provides) is bound to.
      def task_port_for(srv_model, srv_port_name)
        task_model.find_port(port_mappings.fetch(model.port_mappings_for(srv_model).fetch(srv_port_name)))
      end

      # Two views of one service through the same model are equal.
      def ==(other)
        other.is_a?(BoundDataService) && other.task_model.equal?(task_model) &&
          other.full_name == full_name && other.model.equal?(model)
      end
      alias eql? ==

      def hash
        [task_model, full_name, model].hash
      end

      def to_s
        "service '#{full_name}' (#{model}) of #{task_model.name}"
      end

      private

      def bind_by_name_or_type(task)
        if component_model.placeholder?
          base_srv = component_model.proxied_component_model.find_data_service(name)
          return base_srv ? Syskit::BoundDataService.new(task, base_srv) : task.find_data_service_from_type(model)
        end

        resolved = task.find_data_service(full_name)
        return resolved if resolved&.model&.same_service?(self)

        raise InternalError, "#{task} fullfills #{component_model} but has no service standing for #{self}"
      end

      def options_frozen(options)
        options.frozen? ? options : options.dup.freeze
      end
    end
  end
end
