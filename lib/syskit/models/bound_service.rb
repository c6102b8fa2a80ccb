# frozen_string_literal: true

module Syskit
  module Models
    # A service provided by a task model, from +provides+ or +driver_for+:
    # its name (+as:+), the service model and which task port each service
    # port is. A service declared +slave_of:+ another has that service as
    # its +master+ and is named after it (+stereo.left+).
    class BoundService
      NO_OPTIONS = {}.freeze
      private_constant :NO_OPTIONS

      attr_reader :task_model, :name, :model, :port_mappings, :declared_at, :master

      # The dynamic service this one is an instance of (nil for a service
      # the task model declares itself), and the options given for it
      # (+require_dynamic_service('export', as: 'x', joint_names: [...])+):
      # a configure method reads them (+srv.model.dynamic_service_options+).
      attr_reader :dynamic_service, :dynamic_service_options

      def initialize(task_model, name, model, port_mappings, location, master: nil,
                     dynamic_service: nil, dynamic_service_options: NO_OPTIONS)
        @task_model = task_model
        @name = name
        @model = model
        @port_mappings = port_mappings.freeze
        @declared_at = location
        @master = master
        @dynamic_service = dynamic_service
        @dynamic_service_options = options_frozen(dynamic_service_options)
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

      # The device or bus model the task drives through this service, if any.
      def driven_device_model
        model.driven_device_model
      end

      # The task argument holding the device (+f9_dev+ for +as: 'f9'+).
      def argument_name
        @argument_name ||= :"#{name}_dev"
      end

      def fullfills?(other)
        model.fullfills?(other)
      end

      # This service of +task+ (a task of a network), as its configure
      # method sees it (see Syskit::BoundService).
      def bind(task)
        Syskit::BoundService.new(task, self)
      end

      # The task port a port of +srv_model+ (this service's model or one it
      # provides) is bound to.
      def task_port_for(srv_model, srv_port_name)
        task_model.find_port(port_mappings.fetch(model.port_mappings_for(srv_model).fetch(srv_port_name)))
      end

      def to_s
        "service '#{full_name}' (#{model}) of #{task_model.name}"
      end

      private

      def options_frozen(options)
        options.frozen? ? options : options.dup.freeze
      end
    end
  end
end
