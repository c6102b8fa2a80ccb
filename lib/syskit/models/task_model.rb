# frozen_string_literal: true

require 'syskit/models/bound_service'
require 'syskit/models/port_mapper'

module Syskit
  module Models
    # The class-level side of task models. Every task context of a loaded
    # .orogen file is a subclass of Syskit::TaskContext extended with this
    # module, so that +Syskit.extend_model OroGen.lib.Task do ... end+ is a
    # plain +class_eval+: +driver_for+, +provides+ and +stub+ are class
    # methods, +def configure+ defines the method the generator runs.
    module TaskModel
      attr_reader :spec

      # A new task model for +spec+, subclassing this one.
      def new_model(spec)
        model = Class.new(self)
        model.send(:setup_model, spec)
        model
      end

      def name
        spec ? spec.name : super
      end

      def to_s
        name
      end

      def inspect
        name
      end

      def abstract?
        spec&.abstract?
      end

      # Static ports by name (inherited ones included).
      def ports
        spec ? spec.all_ports : {}
      end

      def find_port(name)
        ports[name.to_s]
      end

      def dynamic_ports
        spec ? spec.all_dynamic_ports : []
      end

      # Property declarations by name (inherited ones included).
      def property_declarations
        spec ? spec.all_properties : {}
      end

      # Services by name, inherited ones included.
      def services
        inherited = superclass.respond_to?(:services) ? superclass.services : {}
        inherited.merge(@services || {})
      end

      def find_service(name)
        services[name.to_s]
      end

      # Declares that this task drives devices of +model+; the device is given
      # to the task as its +<as>_dev+ argument. Ports of the device model are
      # bound by name and type, or by +'device_port' => 'task_port'+ mappings.
      def driver_for(model, as: nil, **mappings)
        location = Location.of_caller
        unless model.is_a?(DeviceModel)
          raise DeclarationError.new(
            "driver_for expects a device or bus model, got #{model.inspect}", location: location,
            hint: model.is_a?(DataServiceModel) ? "#{model} is a data service: use provides #{model}, as: 'name'" : nil
          )
        end

        as ||= Naming.underscore(model.name.to_s.split('::').last)
        add_service(as, model, mappings, location)
      end

      # Declares that this task provides the data service +model+ under the
      # name +as+, with optional +'service_port' => 'task_port'+ mappings.
      def provides(model, as: nil, **mappings)
        location = Location.of_caller
        unless model.is_a?(DataServiceModel)
          raise DeclarationError.new("provides expects a data service model, got #{model.inspect}",
                                     location: location)
        end
        unless as
          raise DeclarationError.new("provides #{model} needs a service name", location: location,
                                                                                hint: "write provides #{model}, as: 'name'")
        end

        add_service(as, model, mappings, location)
      end

      # Stands for what the real component does at configure time, when
      # the network is generated without it (e.g. creating per-device ports
      # from the property the configure method just set).
      def stub(&block)
        (@stub_blocks ||= []) << block
        block
      end

      def stub_blocks
        inherited = superclass.respond_to?(:stub_blocks) ? superclass.stub_blocks : []
        inherited + (@stub_blocks || [])
      end

      # Timing statement of real bundles; recorded, used to size buffers.
      def worstcase_processing_time(seconds = nil)
        return @worstcase_processing_time || spec&.worstcase_processing_time if seconds.nil?

        @worstcase_processing_time = seconds
      end

      # Services through which this task drives a device or a bus.
      def driver_services
        services.values.select(&:driven_device_model)
      end

      # Those of {#driver_services} that can drive a device of +device_model+:
      # the service's device model must be it or provide it.
      def driver_services_for(device_model)
        driver_services.select { |srv| srv.driven_device_model.fullfills?(device_model) }
      end

      def driven_device_models
        driver_services.map(&:driven_device_model).uniq
      end

      # The class of this model's +properties+ objects.
      def properties_class
        @properties_class ||= Properties.for(self)
      end

      # The class of the objects +stub+ blocks are evaluated on.
      def stub_context_class
        @stub_context_class ||= StubContext.for(self)
      end

      private

      def setup_model(spec)
        @spec = spec
        @services = {}
        @stub_blocks = []
      end

      def add_service(name, model, mappings, location)
        name = name.to_s
        check_service_options(name, mappings, location)
        existing = find_service(name)
        if existing
          raise DeclarationError.new("#{self.name} already has a #{existing} declared at #{existing.declared_at}",
                                     location: location, hint: "give this one another name with as: 'other_name'")
        end

        port_mappings = PortMapper.new(self, model, mappings, location).map
        srv = BoundService.new(self, name, model, port_mappings, location)
        (@services ||= {})[name] = srv
        argument = srv.argument_name
        define_method(argument) { arguments[argument] } if srv.driven_device_model
        srv
      end

      def check_service_options(name, mappings, location)
        unless name.match?(/\A[a-z_]\w*\z/)
          raise DeclarationError.new("'#{name}' is not a valid service name", location: location,
                                                                             hint: "use a lower-case name, e.g. as: 'gps'")
        end
        options = mappings.keys.grep(Symbol)
        return if options.empty?

        raise DeclarationError.new(
          "unknown option #{options.map { |o| "#{o}:" }.join(', ')}", location: location,
          hint: "the only option is as: 'name'; port mappings are written 'service_port' => 'task_port'"
        )
      end
    end
  end
end
