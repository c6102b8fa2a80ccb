# frozen_string_literal: true

module Syskit
  class InstanceRequirements
    # Syskit's readers on requirements: +x_srv+ for each service of the
    # component model (+Base.tracker_def.rear_pose_srv+: the same
    # requirements, that service selected) and +x_child+ for each child of
    # a composition (+Base.watch_def.pose_child+). No method_missing: the
    # readers are methods of a module per set of names, extended into the
    # requirements when they are made. Part of InstanceRequirements.
    module Readers
      # The reader modules by their method names (shared by every model
      # with those names: they hold no model).
      MODULES = {} # rubocop:disable Style/MutableConstant -- a cache
      LOCK = Mutex.new

      # The module of readers for +model+ (a task or composition model), or
      # nil when it has nothing to read.
      def self.for(model)
        return unless model.is_a?(Class)

        services = service_names(model)
        children = child_names(model)
        ports = port_names(model)
        return if services.empty? && children.empty? && ports.empty?

        key = [services, children, ports].freeze
        LOCK.synchronize { MODULES[key] ||= build(services, children, ports) }
      end

      # The names of the ports of +model+ and of its services (readers
      # x_port, see #find_port).
      def self.port_names(model)
        own = model.respond_to?(:ports) ? model.ports.keys : []
        services = model.respond_to?(:each_data_service) ? model.each_data_service.to_a : []
        served = services.flat_map { |s| s.model.ports.keys }
        (own + served).uniq
      end

      # The names of +model+'s master services (readers x_srv).
      def self.service_names(model)
        model.respond_to?(:each_data_service) ? model.each_data_service.select(&:master?).map(&:name) : []
      end

      # The names of +model+'s children (readers x_child).
      def self.child_names(model)
        model.respond_to?(:child_names) ? model.child_names : []
      end

      def self.build(services, children, ports)
        Module.new do
          services.each { |name| define_method("#{name}_srv") { find_data_service(name) } }
          children.each { |name| define_method("#{name}_child") { find_child(name) } }
          ports.each do |name|
            define_method("#{name}_port") do
              find_port(name) || raise(NoMethodError.new("#{self} has no port '#{name}'", "#{name}_port"))
            end
          end
        end
      end

      # The port +name+ of the selected service, or of the model when none
      # is selected (nil when there is none), as a port of these
      # requirements (Syskit's: +component_model+ is the requirements; see
      # #self_port_to_component_port).
      def find_port(name)
        owner = model
        port = owner.respond_to?(:find_port) ? owner.find_port(name) : nil
        return unless port

        port.class.new(self, port.orogen_port, name.to_s)
      end

      # The port of the component +port+ (one of these requirements' ports)
      # stands for, as Syskit's: itself without a selected service, else the
      # port of the requirements without the service (#to_component_model)
      # that the service's port maps to.
      def self_port_to_component_port(port)
        return port unless service

        mapped = model.find_port(port.name).to_component_port
        mapped.class.new(to_component_model, mapped.orogen_port, mapped.name)
      end

      # What add_port_period said of the port +name+ (a
      # NetworkGeneration::PortDynamics), nil when nothing was.
      def find_port_dynamics(name)
        port_dynamics[name.to_s]
      end

      # These requirements with the service +name+ of the component model
      # selected (nil when it has none).
      def find_data_service(name)
        srv = component_model.respond_to?(:find_service) ? component_model.find_service(name) : nil
        srv && copy(service: srv)
      end

      # The service of the model that provides +service_model+ (the
      # selected one, when it does; one of the placeholder standing for the
      # required services when there is no component model): an
      # AmbiguousServiceSelection when several do.
      def find_data_service_from_type(service_model)
        if service
          return self if service.fullfills?(service_model)

          raise AmbiguousServiceSelection.new(
            "#{self} selects #{service}, which is not a #{service_model}, and #{model} provides it too",
            location: Location.of_caller, hint: "select the #{service_model} service of #{model}"
          )
        end

        check_unambiguous_service(service_model)
        found = proxy_model.find_data_service_from_type(service_model)
        found && copy(service: found)
      end

      # A service model both the component model and a required service
      # model provide does not say which service it is.
      def check_unambiguous_service(service_model)
        component = component_model
        return unless component&.fullfills?(service_model)

        also = models.grep(Models::DataServiceModel).find { |m| !component.fullfills?(m) && m.fullfills?(service_model) }
        return unless also

        raise AmbiguousServiceSelection.new(
          "#{component} and #{also} both provide #{service_model} in #{self}",
          location: Location.of_caller, hint: "select the #{service_model} service explicitly (x_srv)"
        )
      end

      # The child +name+ of the composition model (as +Cmp.use(...).x_child+),
      # reached from these requirements (its +composition_model+, as in
      # Syskit); an ArgumentError when they are not a composition's.
      def find_child(name)
        unless composition?
          raise DeclarationError.new("#{self} is not a composition: it has no child '#{name}'",
                                     location: Location.of_caller, hint: 'ask a composition model for its children')
        end

        component_model.find_child(name)&.attach(self)
      end

      # Enumerates the children of the composition model.
      def each_child(&)
        return enum_for(__method__) unless composition?

        component_model.each_child(&)
      end

      # The selections in effect for these requirements' children, as one
      # injection (Syskit's +resolved_dependency_injection+): a profile
      # definition's profile's (its robot's devices, used profiles and
      # own use), then its own; defaults resolved to explicit selections.
      def resolved_dependency_injection
        context = profile.respond_to?(:dependency_injection_context) ? profile.dependency_injection_context : nil
        (context || DependencyInjectionContext::EMPTY).with(selections).current_state
      end

      # The same requirements without a selected service (Syskit's
      # +to_component_model+).
      def to_component_model
        copy(service: nil)
      end

      # Why +name+ is not a method of the requirements when it looks like
      # a service's or a child's reader (see UserCode.explain).
      def explain_missing(name)
        suffix, what, plural = [%w[_srv service services], %w[_child child children]].find { |s, _| name.end_with?(s) }
        return unless suffix

        wanted = name.delete_suffix(suffix)
        names = what == 'service' ? Readers.service_names(component_model) : Readers.child_names(component_model)
        hint = if names.empty? then "#{component_model || models.join(', ')} has no #{plural}"
               else "its #{plural}: #{names.join(', ')}"
               end
        ["#{self} has no #{what} '#{wanted}'#{Naming.did_you_mean(wanted, names)}", hint]
      end
    end
  end
end
