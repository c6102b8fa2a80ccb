# frozen_string_literal: true

module Syskit
  # A service of a task in a generated network, as Syskit's
  # BoundDataService: what +each_required_dynamic_service+ yields to a
  # configure method.
  #
  #   each_required_dynamic_service do |srv|
  #     next unless srv.fullfills?(Devices::Gazebo::Joint)
  #
  #     srv.name                                   # 'left_wheel'
  #     srv.model.dynamic_service_options          # { joint_names: [...] }
  #     srv.joints_status_port                     # the task's port behind it
  #     find_device_attached_to(srv)               # the device it drives
  #   end
  #
  # Its +model+ is the task model's service (a Models::BoundDataService); it is
  # seen through +service_model+ (the service's model, or one it provides
  # after +as+), whose ports it has as +x_port+.
  class BoundDataService
    attr_reader :component, :model, :service_model

    def initialize(component, model, service_model = model.model)
      @component = component
      @model = model
      @service_model = service_model
      service_model.ports.each_key do |name|
        define_singleton_method("#{name}_port") { find_port(name) }
      end
      model.each_slave_data_service do |slave|
        define_singleton_method("#{slave.name}_srv") { find_data_service(slave.name) }
      end
    end

    # Its slave service +name+ (+task.stereo_srv.find_data_service('left')+),
    # bound to the same component.
    def find_data_service(name)
      component.find_data_service("#{full_name}.#{name}")
    end

    # The service models it fullfills: its service model and those it provides.
    def each_fullfilled_model(&)
      service_model.each_fullfilled_model(&)
    end

    def name
      model.name
    end

    def full_name
      model.full_name
    end

    def master?
      model.master?
    end

    # Whether the service provides +other+ (a data service model).
    def fullfills?(other)
      service_model.fullfills?(other)
    end

    # The service seen through +other+, a model it provides: its ports are
    # then +other+'s.
    def as(other)
      return self if other.equal?(service_model)
      return BoundDataService.new(component, model, other) if fullfills?(other)

      raise ArgumentError, "#{self} does not provide #{other}"
    end

    # The service port +name+ (a Syskit::Port whose component is this
    # service; +to_component_port+ is the task's port behind it), or nil.
    # Its model is the port of the task model's service (+model+, seen as
    # +service_model+), as in Syskit: +port.model.component_model+ is the
    # service of the task's model, a specialization's once the task is
    # specialized.
    def find_port(name)
      return unless service_model.find_port(name)

      seen = model.as(service_model)
      Port.new(seen.find_output_port(name) || seen.find_input_port(name), self)
    end

    # Its service ports (see #find_port).
    def each_port
      return enum_for(__method__) unless block_given?

      service_model.each_port { |port_model| yield find_port(port_model.name) }
    end

    # The task's port behind +port+, a port of this service.
    def self_port_to_component_port(port)
      component.find_port(model.task_port_for(service_model, port.name).name)
    end

    # As #find_port, for an input (output) port of the service only.
    def find_input_port(name)
      find_port(name) if service_model.find_input_port(name)
    end

    def find_output_port(name)
      find_port(name) if service_model.find_output_port(name)
    end

    def ==(other)
      other.is_a?(BoundDataService) && other.component.equal?(component) && other.model.equal?(model)
    end
    alias eql? ==

    def hash
      [component, model].hash
    end

    def to_s
      "#{component}.#{full_name}_srv"
    end
    alias inspect to_s
  end
end
