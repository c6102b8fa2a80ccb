# frozen_string_literal: true

module Syskit
  class DependencyInjection
    # Syskit's functions on selection tables (key => selected value), as
    # +use+ builds them and the generator reads them: checking a selection,
    # following selections that name other selected keys, turning defaults
    # into keyed selections, resolving names. Plain functions of their
    # arguments; part of DependencyInjection.
    module Selections
      # The roots of the model hierarchies: every component or service
      # fullfills them, so a default never selects itself for them.
      def ignored_models
        [Syskit::DataService, Syskit::Device, Syskit::ComBus, Syskit::Component, Syskit::TaskContext,
         Syskit::RubyTaskContext, Syskit::Composition]
      end

      # +selection+ (key => value) with its keys and values checked, as
      # +use+ accepts them: keys are names, component models or data
      # service models (+location+: where, for errors); a component
      # selected for a data service is narrowed to its service of that
      # type.
      def normalize_selection(selection, location = Location.of_caller)
        selection.each_with_object({}) do |(key, value), normalized|
          key = normalize_key(key, location)
          value = normalize_selected_object(value, key, location)
          normalized[key] = key.is_a?(Module) ? narrow_to_key(key, value, location) : value
        end
      end

      # +value+ checked as something +use+ can select (for +key+, or as a
      # default): a name, a model, a service, a component, requirements,
      # nothing or do_not_inherit; anything else converts with
      # to_instance_requirements or is an ArgumentError.
      def normalize_selected_object(value, key = nil, location = Location.of_caller)
        return value if value.is_a?(String) || value.equal?(NOTHING) || value.equal?(DO_NOT_INHERIT) ||
                        value.is_a?(Syskit::BoundDataService) || InstanceRequirements.selectable?(value)
        return value.to_instance_requirements if value.respond_to?(:to_instance_requirements)

        what = key ? "for #{key_name(key)}" : 'as a default'
        raise DeclarationError.new(
          "use cannot select #{Arguments.shown(value)} #{what}: it is not a model, device or definition",
          location: location,
          hint: 'select a task or composition model, a data service, a device (Base.gps_dev), a definition ' \
                '(Base.x_def) or a requirement (Model.with_arguments(...))'
        )
      end

      # The selection of +name+ in +mappings+: 'child' gives what is
      # selected for 'child', 'child.srv' (or 'child.srv.slave') that
      # selection's service. Nil when nothing, or only another name, is
      # selected for it; a NameResolutionError when the service is unknown.
      def find_name_resolution(name, mappings)
        object_name, service_name = name.split('.', 2)
        selected = mappings[object_name]
        return if selected.nil? || selected.is_a?(String)
        return selected unless service_name

        unless selected.respond_to?(:find_data_service)
          raise NameResolutionError.new("cannot select the service '#{service_name}' of #{selected}",
                                        location: Location.of_caller, hint: 'only components have services')
        end

        selected.find_data_service(service_name) ||
          raise(NameResolutionError.new("#{selected} has no service '#{service_name}'",
                                        location: Location.of_caller,
                                        hint: "name one of its services after '#{object_name}.'"))
      end

      # +mapping+ with each value that is itself a selected key (a model,
      # or a service of a selected component model) replaced by what that
      # key selects, until it selects itself; names are not followed.
      def resolve_recursive_selection_mapping(mapping)
        mapping.transform_values { |value| resolve_selection_recursively(value, mapping) }
      end

      # What +value+ ends at following the selections of +mapping+ (see
      # #resolve_recursive_selection_mapping).
      def resolve_selection_recursively(value, mapping)
        seen = []
        loop do
          return value if seen.include?(value)

          seen << value
          following = following_selection(value, mapping)
          return value if following.nil? || placeholder?(following) || following == value

          value = following
        end
      end

      # +explicit+ with the +defaults+ added under each model they
      # fullfill that is not selected already and that no other default
      # fullfills too (nor the same default through two services).
      def resolve_default_selections(explicit, defaults)
        return explicit if defaults.nil? || defaults.empty?

        found = {}
        ambiguous = {}
        defaults.each do |value|
          value = resolve_selection_recursively(value, explicit)
          default_keys(value).each do |model|
            next if explicit.key?(model) || ambiguous.key?(model)

            if found.key?(model) && found[model] != value
              ambiguous[model] = found.delete(model)
            else
              found[model] = value
            end
          end
        end
        explicit.merge(found)
      end

      # Whether +value+ says what not to select rather than what to select.
      def placeholder?(value)
        value.equal?(NOTHING) || value.equal?(DO_NOT_INHERIT)
      end

      private

      # The models a default +value+ selects itself for.
      def default_keys(value)
        models = InstanceRequirements.fullfilled_models_of(value) - ignored_models
        return models unless value.respond_to?(:find_all_data_services_from_type)

        models.reject do |m|
          m.is_a?(Models::DataServiceModel) && value.find_all_data_services_from_type(m).size != 1
        end
      end

      # What +mapping+ selects in place of +value+ (nil when nothing).
      def following_selection(value, mapping)
        case value
        when Models::BoundDataService
          selected = mapping[value.component_model]
          service_on(selected, value) unless selected.nil? || selected.is_a?(String) || placeholder?(selected)
        when Module, Actions::Profile::Tag then mapping[value]
        end
      end

      # The service of +selected+ (a model selected for +srv+'s component
      # model) that stands for +srv+.
      def service_on(selected, srv)
        model = InstanceRequirements.from(selected).component_model
        return selected if selected.is_a?(Models::BoundDataService)
        return srv unless model.respond_to?(:find_data_service_from_type)

        model.find_data_service(srv.full_name) || model.find_data_service_from_type(srv.model) || srv
      end

      def normalize_key(key, location)
        case key
        when String, Symbol then key.to_s
        when Models::CompositionChild then key.path
        when Models::DataServiceModel, Actions::Profile::Tag then key
        else
          return key if key.is_a?(Class) && key < Component

          raise DeclarationError.new(
            "use cannot select for #{Arguments.shown(key)}: keys are child names or models",
            location: location, hint: "write use('child_name' => Model) or use(Services::Pose => Model)"
          )
        end
      end

      def key_name(key)
        key.is_a?(String) ? "'#{key}'" : key.to_s
      end

      # +value+ as selected for the model +key+: it must be that model or
      # fullfill it; a component model's service, or a component, narrows
      # to the component for a component key and to its service of the
      # key's type for a service key. What a component model provides may
      # be declared by a file loaded later: a component model that does
      # not provide a service key yet is kept as it is, and checked where
      # the selection fills a child.
      def narrow_to_key(key, value, location)
        return value if value.is_a?(String) || placeholder?(value)
        return narrow_to_component(key, value, location) if key.is_a?(Class)
        return value if !key.is_a?(Models::DataServiceModel) ||
                        (value.is_a?(Class) && value.find_all_data_services_from_type(key).empty?)

        check_fullfills(key, value, location)
        return value unless value.respond_to?(:find_data_service_from_type) || value.is_a?(AbstractComponent)

        service_of_type(value, key) || value
      end

      # The service of +value+ (a component model, requirements or a task)
      # that is a +service_model+.
      def service_of_type(value, service_model)
        return value.find_data_service_from_type(service_model) unless value.is_a?(AbstractComponent)

        srv = value.model.find_data_service_from_type(service_model)
        srv && Syskit::BoundDataService.new(value, srv)
      end

      def narrow_to_component(key, value, location)
        value = case value
                when Models::BoundDataService then value.component_model
                when Syskit::BoundDataService then value.component
                else value
                end
        check_fullfills(key, value, location)
        value
      end

      def check_fullfills(key, value, location)
        value = value.model if value.is_a?(AbstractComponent)
        return if !value.respond_to?(:fullfills?) || value.fullfills?(key)

        raise DeclarationError.new("use cannot select #{Arguments.shown(value)} for #{key}: it is not a #{key}",
                                   location: location, hint: "select #{key} itself, or #{
                                     key.is_a?(Class) ? 'a submodel of it' : 'a data service that provides it'}")
      end
    end
  end
end
