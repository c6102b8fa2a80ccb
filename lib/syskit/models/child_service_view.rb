# frozen_string_literal: true

require 'syskit/models/port_lookup'
require 'syskit/models/child_port'

module Syskit
  module Models
    class CompositionChild
      # A child seen through one of its service models; through one of the
      # services of its component model (+bound_service+, a BoundDataService)
      # when it comes from find_data_service or
      # find_all_data_services_from_type.
      class ServiceView
        include PortLookup
        include ChildConnections
        include ChildReference

        attr_reader :child, :service_model, :bound_service

        def initialize(child, service_model, bound_service = nil)
          @child = child
          @service_model = service_model
          @bound_service = bound_service
          service_model.ports.each_key do |name|
            define_singleton_method("#{name}_port") { find_port(name) }
          end
        end

        # Syskit's names on a child's service: the service of the component
        # model (+srv.model.model+ is then the service model), its name.
        def model
          bound_service || service_model
        end

        def name
          bound_service&.name
        end

        def composition_model
          child.composition_model
        end

        def child_name
          child.child_name
        end

        # As a selection (+use('x' => tracker_child.rear_pose_srv)+): the
        # child's task, through this service (see ChildReference).
        def referenced_child
          child
        end

        def referenced_service
          bound_service
        end

        # What the child requires, narrowed to the service.
        def requirements
          return child.requirements unless bound_service

          child.requirements.merge_selection(InstanceRequirements.from(bound_service))
        end

        # The view through the service's own model, whatever it is seen as.
        def as_real_model
          bound_service ? ServiceView.new(child, bound_service.model, bound_service) : self
        end

        # The view through +other+, a model the service provides.
        def as(other)
          raise ArgumentError, "#{self} does not provide #{other}" unless fullfills?(other)

          ServiceView.new(child, other, bound_service)
        end

        def fullfills?(other)
          service_model.fullfills?(other)
        end

        # The ports of the service model; through a service of the child's
        # component model, each is the child's port behind it (+pose_port+
        # of the tracker's rear_pose service is the tracker's +rear_port+).
        def ports
          @ports ||= service_model.ports.to_h do |name, port|
            [name, component_port(name) || ChildPort.new(child, port, service_model)]
          end
        end

        # The child's port behind the service port +name+, nil unless the
        # view is of a service of the child's component model.
        def component_port(name)
          component = child.requirements.component_model
          return unless bound_service && component.is_a?(Class) && component <= bound_service.task_model

          task_port = bound_service.task_port_for(service_model, name)
          child.find_port(task_port.name) if task_port
        end

        # The same view: of the same child (role of the same composition
        # model), through the same model and service.
        def ==(other)
          other.is_a?(ServiceView) && other.child.composition_model.equal?(child.composition_model) &&
            other.child.child_name == child.child_name && other.service_model.equal?(service_model) &&
            other.bound_service.equal?(bound_service)
        end
        alias eql? ==

        def hash
          [child.composition_model, child.child_name, service_model, bound_service].hash
        end

        def to_s
          "#{child}.as(#{service_model})"
        end
      end
    end
  end
end
