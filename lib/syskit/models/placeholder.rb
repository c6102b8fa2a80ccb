# frozen_string_literal: true

module Syskit
  module Models
    # Syskit's placeholder models: "some component that provides these
    # services" (+Syskit::Models::Placeholder.for([Srv1, Srv2])+,
    # +Srv.placeholder_model+, or
    # +Syskit::Component.create_proxy_task_model([...])+). A task model
    # providing each service with its ports, abstract: it selects
    # specializations and stands for a child in tests, and a network that
    # still holds one is refused (or, in tests, stubbed).
    #
    # The list may hold one component model (or one of its services) that
    # the placeholder derives from; the services it already provides are
    # dropped, and when none is left the list means the component itself.
    module Placeholder
      module_function

      # The placeholder of +models+, made once per list.
      def for(models)
        models = Array(models)
        (@placeholders ||= {})[models] ||= build(models)
      end

      def build(models)
        base, services = split(models)
        return base if services.empty?

        component = base.is_a?(BoundDataService) ? base.task_model : base
        model = Network::StubModels.service_provider(services, base: component)
        model.spec.abstract = true
        model.extend(Proxy)
        model.proxied_data_service_models = services.freeze
        model.proxied_component_model = component || Syskit::Component
        model
      end

      # The component model (or service) of +models+, and the services it
      # does not provide yet.
      def split(models)
        bases = models.select { |m| m.is_a?(Class) || m.is_a?(BoundDataService) }
        if bases.size > 1
          raise DeclarationError.new("a placeholder derives from one component model at most, got #{bases.join(', ')}",
                                     location: Location.of_caller, hint: 'give one component model and services')
        end

        base = bases.first
        services = models.grep(DataServiceModel).uniq.reject { |srv| base&.fullfills?(srv) }
        if !base && services.empty?
          raise DeclarationError.new('a placeholder needs models',
                                     location: Location.of_caller)
        end

        [base, services]
      end

      # What a placeholder model says of itself.
      module Proxy
        # The service models it stands for (those of its component model aside).
        attr_accessor :proxied_data_service_models

        # The component model it derives from (Syskit::Component when none
        # was given).
        attr_accessor :proxied_component_model

        def placeholder?
          true
        end
      end
    end
  end
end
