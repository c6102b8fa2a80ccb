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
        return if services.empty? && children.empty?

        key = [services, children].freeze
        LOCK.synchronize { MODULES[key] ||= build(services, children) }
      end

      # The names of +model+'s master services (readers x_srv).
      def self.service_names(model)
        model.respond_to?(:each_data_service) ? model.each_data_service.select(&:master?).map(&:name) : []
      end

      # The names of +model+'s children (readers x_child).
      def self.child_names(model)
        model.respond_to?(:child_names) ? model.child_names : []
      end

      def self.build(services, children)
        Module.new do
          services.each { |name| define_method("#{name}_srv") { find_data_service(name) } }
          children.each { |name| define_method("#{name}_child") { find_child(name) } }
        end
      end

      # These requirements with the service +name+ of the component model
      # selected (nil when it has none).
      def find_data_service(name)
        srv = component_model.respond_to?(:find_service) ? component_model.find_service(name) : nil
        srv && copy(service: srv)
      end

      # The service of the component model that provides +service_model+
      # (the selected one, when it does): an error when several do.
      def find_data_service_from_type(service_model)
        return self if service&.fullfills?(service_model)

        model = component_model
        candidates = model.respond_to?(:services_fulfilling) ? model.services_fulfilling(service_model) : []
        candidates = candidates.select(&:master?)
        return copy(service: candidates.first) if candidates.size == 1
        return nil if candidates.empty?

        names = candidates.map(&:name)
        raise DeclarationError.new("#{self} provides #{service_model} several times (#{names.join(', ')})",
                                   location: Location.of_caller, hint: "select one: #{self}.#{names.first}_srv")
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
