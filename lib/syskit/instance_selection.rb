# frozen_string_literal: true

module Syskit
  # What fills a requirement, as Syskit's InstanceSelection: the
  # requirements asked for (+required+), those selected to fill them
  # (+selected+, of one component model), the task selected when there is
  # one (+component+), and the service of the selected component model
  # that fills each required data service model (+service_selection+).
  # What dependency injection returns (DependencyInjection#instance_selection_for),
  # and what a composition keeps of each child (Composition#child_selection).
  class InstanceSelection
    attr_reader :component, :selected, :required, :service_selection

    # +mappings+: services already chosen for required data service models.
    def initialize(component = nil, selected = InstanceRequirements.new([Component]), # rubocop:disable Metrics/ParameterLists -- Syskit's signature
                   required = InstanceRequirements.new, mappings = {})
      @component = component
      @selected = selected
      @required = required
      @service_selection = InstanceSelection.compute_service_selection(selected, required, mappings).freeze
    end

    # Each data service model +required+ has, with the service of
    # +selected+ that fills it: the one of +mappings+, else the one
    # #service_of finds.
    def self.compute_service_selection(selected, required, mappings)
      required.models.grep(Models::DataServiceModel).each_with_object({}) do |service_model, result|
        found = mappings[service_model] || service_of(selected, service_model)
        result[service_model] = found if found
      end
    end

    # The service of +selected+ that provides +service_model+: the
    # selected one, else the one service of the component model (or of
    # the placeholder standing for the required models) that does (none
    # when several do).
    def self.service_of(selected, service_model)
      return selected.service if selected.service&.fullfills?(service_model)

      model = selected.respond_to?(:proxy_model) ? selected.proxy_model : selected.component_model
      return unless model.respond_to?(:find_all_data_services_from_type)

      found = model.find_all_data_services_from_type(service_model)
      found.first if found.size == 1
    end

    # +{port name of a required data service => port name of the selected
    # component}+, for every required service a service fills.
    def port_mappings
      service_selection.each_with_object({}) do |(service_model, service), result|
        result.merge!(service.port_mappings_for(service_model))
      end
    end

    def to_s
      "#{required} => #{selected}"
    end
    alias inspect to_s
  end
end
