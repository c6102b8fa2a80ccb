# frozen_string_literal: true

module Syskit
  module Models
    # Finding a component model's services by their model, and checking
    # that a model stands for another, as Syskit's component models do.
    # Part of Component (uses #services_fulfilling).
    #
    #   Task.find_data_service_from_type(Pose)       # its only Pose service, or nil
    #   Task.find_all_data_services_from_type(Pose)  # each, seen as a Pose
    module ServiceLookups
      # The service whose model is or provides +srv_model+, seen through
      # +srv_model+; nil if there is none, an AmbiguousServiceSelection if
      # there are several.
      def find_data_service_from_type(srv_model)
        candidates = find_all_data_services_from_type(srv_model)
        return candidates.first if candidates.size <= 1

        names = candidates.map(&:full_name).sort
        raise AmbiguousServiceSelection.new(
          "#{name} has several services of type #{srv_model}: #{names.join(', ')}",
          location: Location.of_caller, hint: "choose one by its name: #{name}.find_data_service('#{names.first}')"
        )
      end

      # Every service whose model is or provides +srv_model+, each seen
      # through +srv_model+ (its ports are +srv_model+'s), in declaration order.
      def find_all_data_services_from_type(srv_model)
        return [] unless srv_model.is_a?(DataServiceModel)

        services_fulfilling(srv_model).map { |srv| srv.as(srv_model) }
      end

      # +object+ itself if it stands for this model (Syskit's +try_bind+):
      # a model or a task that fullfills it, or a service of this model or
      # of a submodel; nil otherwise.
      def try_bind(object)
        return object if object.is_a?(BoundDataService) && object.task_model <= self

        object if object.respond_to?(:fullfills?) && object.fullfills?(self)
      end

      # As #try_bind, but an error when +object+ does not stand for this model.
      def bind(object)
        found = try_bind(object)
        return found if found

        raise DeclarationError.new("cannot bind #{name} to #{object}",
                                   location: Location.of_caller, hint: "give #{name}, a submodel or a task of it")
      end

      # Syskit's deprecated name of #bind.
      def resolve(object)
        Compat::Roby.warn_deprecated('resolve is deprecated, use Models::Component#bind instead')
        bind(object)
      end

      # Syskit's deprecated name of #try_bind.
      def try_resolve(object)
        Compat::Roby.warn_deprecated('try_resolve is deprecated, use Models::Component#try_bind instead')
        try_bind(object)
      end

      # The component's port of a port of its own (Syskit's identity, beside
      # the one of bound services): +port+ itself.
      def self_port_to_component_port(port)
        port
      end
    end
  end
end
