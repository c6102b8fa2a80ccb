# frozen_string_literal: true

module Syskit
  module Models
    # Syskit's placeholder models: "some component that provides these
    # services" (+Syskit::Models::Placeholder.for([Srv1, Srv2])+, or
    # +Syskit::Component.create_proxy_task_model([...])+). A task model
    # providing each service with its ports, abstract: it selects
    # specializations and stands for a child in tests, and a network that
    # still holds one is refused (or, in tests, stubbed).
    module Placeholder
      module_function

      # The placeholder of +models+ (data services, and at most one
      # component model it is a submodel of), made once per list.
      def for(models)
        models = Array(models)
        (@placeholders ||= {})[models] ||= build(models)
      end

      def build(models)
        base = models.find { |m| m.is_a?(Class) }
        services = models.grep(DataServiceModel)
        model = Network::StubModels.service_provider(services, base: base)
        model.spec.abstract = true
        model
      end
    end
  end
end
