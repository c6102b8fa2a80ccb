# frozen_string_literal: true

require 'syskit/models/bound_data_service'
require 'syskit/models/port_mapper'

module Syskit
  module Models
    # The data services a component model provides (+provides Srv, as:
    # 'name'+, each then reachable as +name_srv+), inherited ones
    # included. Part of Component (uses its cache).
    module ServiceDeclarations
      # Services by name, inherited ones included.
      # Those of the parent model are promoted to this one (their
      # +component_model+ is this model, as in Syskit), so that selecting
      # +Sub.gps_srv+ selects Sub.
      def services
        cached(:services) do
          inherited = superclass.respond_to?(:services) ? superclass.services : {}
          own = @services || {}
          promoted = {}
          inherited.each do |full_name, srv|
            promoted[full_name] = own[full_name] || promote(srv, own, promoted)
          end
          promoted.merge(own).freeze
        end
      end

      # Services whose model is or provides +service_model+, in declaration order.
      def services_fulfilling(service_model)
        cached(:fulfilling, service_model) { services.values.select { |srv| srv.fullfills?(service_model) }.freeze }
      end

      # The service of full name +name+ ('gps', or 'stereo.left' for a slave).
      def find_service(name)
        services[name.to_s]
      end
      alias find_data_service find_service

      # Enumerates the services, inherited ones included, in declaration order.
      def each_data_service(&)
        services.each_value(&)
      end

      # +{service port name => component port name}+ binding the ports of
      # +service_model+ to this model's (Syskit's +compute_port_mappings+),
      # +explicit+ mappings first, as +provides+ binds them; an
      # InvalidPortMapping when a port has no match or several.
      def compute_port_mappings(service_model, explicit = {})
        PortMapper.new(self, service_model, explicit, Location.of_caller, error_class: InvalidPortMapping).map
      end

      # Declares that this component provides the data service +model+ under
      # the name +as+, with optional +'service_port' => 'component_port'+
      # mappings; +slave_of: 'name'+ makes it a slave of the service +name+
      # (its full name is then +name.as+).
      def provides(model, mappings = {}, as: nil, slave_of: nil, **more)
        location = Location.of_caller
        return provides_task_service(model) if model.is_a?(Compat::Roby::TaskServiceModel) && as.nil?

        unless model.is_a?(DataServiceModel)
          raise DeclarationError.new("provides expects a data service model, got #{model.inspect}",
                                     location: location, hint: NotAModel.hint('provides', model, location))
        end
        unless as
          raise DeclarationError.new("provides #{model} needs a service name",
                                     location: location, hint: "write provides #{model}, as: 'name'")
        end

        add_service(as, model, mappings.merge(more), location, slave_of: slave_of)
      end

      private

      # A Roby task service (+provides Syskit::LoggerService+) has no name
      # or ports: the model and its tasks are of it, as in Roby, where it
      # is a module of the task model.
      def provides_task_service(model)
        include(model)

        Component.declarations_changed
        model
      end

      def add_service(name, model, mappings, location, slave_of: nil)
        name = name.to_s
        check_service_options(name, mappings, location)
        master = master_service(slave_of, location) if slave_of
        full_name = master ? "#{master.full_name}.#{name}" : name
        existing = find_service(full_name)
        check_override(existing, model, location) if existing

        port_mappings = PortMapper.new(self, model, mappings, location).map
        register_service(BoundDataService.new(self, name, model, port_mappings, location, master: master))
      end

      # Makes +srv+ (a BoundDataService of this model) one of its services.
      def register_service(srv)
        (@services ||= {})[srv.full_name] = srv
        include_service_models(srv)
        Component.declarations_changed
        define_service_reader(srv)
        srv.master&.define_slave_reader(srv)
        srv
      end

      # Its tasks are of the service models it provides, as in Syskit, where
      # these are modules of the task model (+task.is_a?(Srv)+).
      def include_service_models(srv)
        srv.each_fullfilled_model.to_a.reverse_each { |m| include(m) if m.is_a?(DataServiceModel) }
      end

      # +name_srv+ on the model and its tasks, for a master service:
      # Syskit's way of selecting one service of a component
      # (+use('pose' => Task.gps_srv)+).
      # Submodels inherit the reader and get their own (promoted) service.
      def define_service_reader(srv)
        return unless srv.master?

        reader = "#{srv.name}_srv"
        name = srv.full_name
        define_singleton_method(reader) { find_service(name) } unless singleton_class.method_defined?(reader, false)
        define_method(reader) { find_data_service(name) } unless method_defined?(reader, false)
      end

      # A parent's service +srv+ as a service of this model, its master
      # being this model's (+own+ or already +promoted+).
      def promote(srv, own, promoted)
        master = srv.master && (own[srv.master.full_name] || promoted[srv.master.full_name])
        copy = srv.attach(self, master: master)
        master&.define_slave_reader(copy)
        copy
      end

      # A submodel may declare again a service of its parent model, with
      # the parent service's model or one providing it (a driver package's
      # subclass driving a more specific device); a service is declared
      # once per model.
      def check_override(existing, model, location)
        existing = existing.demoted
        if @services&.key?(existing.full_name)
          raise DeclarationError.new("#{name} already has a #{existing} declared at #{existing.declared_at}",
                                     location: location, hint: "give this one another name with as: 'other_name'")
        end
        return if model.fullfills?(existing.model)

        raise DeclarationError.new(
          "#{model} cannot replace the #{existing} declared at #{existing.declared_at}: " \
          "it does not provide #{existing.model}",
          location: location,
          hint: "give the service another name with as: 'other_name', or use a model providing #{existing.model}"
        )
      end

      def master_service(slave_of, location)
        name = slave_of.respond_to?(:full_name) ? slave_of.full_name : slave_of.to_s
        found = find_service(name)
        return found if found

        known = services.keys.sort
        hint = known.empty? ? "declare the master first: driver_for Model, as: 'name'" : "services: #{known.join(', ')}"
        raise DeclarationError.new(
          "slave_of: '#{name}' names no service of #{self.name}#{Naming.did_you_mean(name, known)}",
          location: location, hint: hint
        )
      end

      def check_service_options(name, mappings, location)
        # Syskit takes any name (common_models names services after their
        # models: as: 'Test'; its tests after anonymous ones, as: srv.to_s)
        # but a dot, which separates a slave's name from its master's.
        if name.empty? || name.include?('.')
          raise DeclarationError.new("'#{name}' is not a valid service name",
                                     location: location, hint: "use a name without dots, e.g. as: 'gps'")
        end
        options = mappings.keys.grep(Symbol)
        return if options.empty?

        raise DeclarationError.new(
          "unknown option #{options.map { |o| "#{o}:" }.join(', ')}",
          location: location,
          hint: "the only option is as: 'name'; port mappings are written 'service_port' => 'task_port'"
        )
      end
    end
  end
end
