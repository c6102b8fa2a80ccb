# frozen_string_literal: true

module Syskit
  module Models
    class CompositionChild
      # What a child overloaded in a submodel (+overload 'pose', Odometry+)
      # knows of the child it overloads, as Syskit's. Part of
      # CompositionChild (reads +requirements+; +@overload_info+ is reset
      # when they change).
      module Overload
        # The child of a parent model this one overloads (Syskit's
        # +parent_model+), nil when it overloads none.
        attr_reader :parent_model

        # What the overload made of the child it overloads (Syskit's
        # +overload_info+): an InstanceSelection of this child's requirements
        # (+selected+, through the service that fills the overloaded child's
        # service) for the overloaded child (+required+).
        def overload_info
          @overload_info ||= begin
            required = parent_model || InstanceRequirements.new
            InstanceSelection.new(nil, overload_selected(required), required)
          end
        end

        # +{port name on the overloaded child => port name on this one}+
        # (Syskit's +port_mappings+ of a child).
        def port_mappings
          overload_info.port_mappings
        end

        private

        # The requirements with the service of the component model that
        # fills the one data service model +required+ has, when one does.
        def overload_selected(required)
          component = requirements.component_model
          services = required.models.grep(DataServiceModel)
          return requirements if requirements.service || !component || services.size != 1

          found = component.find_all_data_services_from_type(services.first)
          found.size == 1 ? requirements.select_service(component.find_service(found.first.full_name)) : requirements
        end
      end
    end
  end
end
