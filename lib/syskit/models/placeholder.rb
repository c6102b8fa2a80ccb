# frozen_string_literal: true

require 'syskit/placeholder'
require 'syskit/models/placeholder_creation'

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
    #
    # Placeholder models extend this module (+model.kind_of?(Placeholder)+);
    # how they are made is in Creation, which Placeholder extends.
    module Placeholder
      extend Creation

      # The service models it stands for (those of its component model aside).
      attr_reader :proxied_data_service_models

      # The component model it derives from (Syskit::Component for
      # services alone).
      attr_reader :proxied_component_model

      def placeholder?
        true
      end

      def abstract?
        true
      end

      # A placeholder is not a specialization: it stands for itself.
      def concrete_model
        self
      end

      # What it derives from, as Syskit's placeholders say it.
      def supermodel
        proxied_component_model
      end

      def name
        @placeholder_name || super
      end

      def to_s
        name
      end

      def inspect
        name
      end

      # Its component model's fullfilled models (none for Syskit::Component),
      # then its services' and Syskit::AbstractComponent: not the task model
      # class the gem builds it from.
      def fullfilled_model
        models = []
        models.concat(proxied_component_model.fullfilled_model) unless proxied_component_model.equal?(Syskit::Component)
        proxied_data_service_models.each { |srv| models.concat(srv.fullfilled_models) }
        models.delete(Syskit::AbstractComponent)
        (models.uniq << Syskit::AbstractComponent).freeze
      end

      # Whether +model+ (a component model or placeholder) stands for
      # everything this placeholder stands for.
      def fullfilled_by?(model)
        (proxied_component_model.equal?(Syskit::Component) || model.fullfills?(proxied_component_model)) &&
          proxied_data_service_models.all? { |srv| model.fullfills?(srv) }
      end

      # The placeholder standing for both this one and +other+ (a component
      # model, a placeholder, or a service of one): self or +other+ when one
      # stands for the other, else the placeholder of the merged component
      # models and of both service lists.
      def merge(other)
        if other.is_a?(BoundDataService)
          merged = merge(other.component_model)
          return merged.find_service(other.full_name) || merged.find_data_service_from_type(other.model)
        end
        return self if other.is_a?(Placeholder) ? other.fullfilled_by?(self) : fullfills?(other)
        return other if fullfilled_by?(other)

        other_base = other.is_a?(Placeholder) ? other.proxied_component_model : other
        other_services = other.is_a?(Placeholder) ? other.proxied_data_service_models : []
        Placeholder.for((proxied_data_service_models + other_services).to_set,
                        component_model: proxied_component_model.merge(other_base))
      end
    end
  end
end
