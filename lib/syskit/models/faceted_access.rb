# frozen_string_literal: true

require 'set'
require 'syskit/models/port_lookup'

module Syskit
  module Models
    # A model (or requirements) seen through other models it fullfills, as
    # Syskit's FacetedAccess (+Task.to_instance_requirements.as(Srv)+): the
    # ports are the required models' (+required+, a placeholder model or a
    # data service model), each standing for the port of +object+ it maps
    # to.
    class FacetedAccess
      include PortLookup

      attr_reader :object, :required

      def initialize(object, required)
        @object = object
        @required = required
        @ports = {}
      end

      # The models +required+ stands for: the services of a placeholder and
      # the component model it derives from, or +required+ itself.
      def required_models
        return [required] unless required.respond_to?(:placeholder?) && required.placeholder?

        base = required.proxied_component_model
        required.proxied_data_service_models + (base == Syskit::Component ? [] : [base])
      end

      # The ports named +name+ of each of the required models.
      def find_ports_on_required(name)
        required_models.filter_map { |model| FacetedAccess.port_model(model, name.to_s) }
      end

      # The ports of the object that the required ports named +name+ map
      # to (a set: several required ports may map to the same one).
      def find_all_port_mappings_for(name)
        required_models.each_with_object(Set.new) do |model, found|
          port = model.find_port(name.to_s)
          mapped = port && object_port(model, name.to_s)
          found << mapped if mapped
        end
      end

      # The facet's port +name+: nil when no required model has it, an
      # AmbiguousPortOnCompositeModel error when they map it to different
      # ports of the object.
      def find_port(name)
        name = name.to_s
        @ports.fetch(name) { @ports[name] = facet_port(name) }
      end

      def has_port?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        !find_port(name).nil?
      end

      # Syskit's +selected+: the object's requirements, with the service
      # of its component model that provides the required data service
      # selected when one data service alone is required.
      def selected
        requirements = object.to_instance_requirements
        models = required_models
        return requirements if requirements.service || models.size != 1 || !models.first.is_a?(DataServiceModel)

        requirements.find_data_service_from_type(models.first)&.as(models.first) || requirements
      end

      # The ports of the required models, as the facet's.
      def ports
        names = required_models.flat_map { |model| model.ports.keys }.uniq
        names.to_h { |name| [name, find_port(name)] }.compact
      end

      # The port of the object a port of the facet stands for.
      def self_port_to_component_port(port)
        find_all_port_mappings_for(port.name).first
      end

      # Connects the facet's ports to +sink+'s by type (see ChildPort).
      def connect_to(sink, policy = {})
        each_output_port.each do |out|
          target = out.to_component_port
          target.connect_to(sink, policy) if target.respond_to?(:connect_to)
        end
      end

      def to_s
        "#{object}.as(#{required_models.join(',')})"
      end
      alias inspect to_s

      # The port +name+ of +model+ as Syskit's port readers give it
      # (+Task.out_port+), nil when it has none.
      def self.port_model(model, name)
        model.find_output_port(name) || model.find_input_port(name)
      end

      private

      def facet_port(name)
        mapped = find_all_port_mappings_for(name)
        return if mapped.empty?

        if mapped.size > 1
          raise AmbiguousPortOnCompositeModel.new(
            "#{self}.#{name} stands for several ports of #{object}: #{mapped.map(&:name).sort.join(', ')}",
            location: Location.of_caller, hint: 'see the object through one model only (as(Srv))'
          )
        end

        port = find_ports_on_required(name).first
        # A port of the facet stands for the port of the object it maps to
        # (see #self_port_to_component_port).
        port.attach(self)
      end

      # The port of the object that port +name+ of +model+ (a required
      # model) maps to.
      def object_port(model, name)
        component = object.is_a?(InstanceRequirements) ? object.component_model : object
        return unless component
        return FacetedAccess.port_model(component, name) unless model.is_a?(DataServiceModel)

        service = component.find_data_service_from_type(model)
        port = service&.task_port_for(model, name)
        port && FacetedAccess.port_model(component, port.name)
      end
    end
  end
end
