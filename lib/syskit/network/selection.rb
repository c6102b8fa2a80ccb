# frozen_string_literal: true

module Syskit
  module Network
    # What fills a composition's child, from the dependency injection in
    # effect (see DependencyInjectionContext): one function of (child,
    # context), used by the generator and by +narrow+.
    module Selection
      # The selected requirements of a child (the child's own when nothing
      # is selected), the injection keys used, whether the child was
      # selected by name, and, when the selection is another child of an
      # enclosing composition, that child (+reference+).
      Result = Struct.new(:requirements, :used_keys, :explicit, :reference)

      module_function

      # An injection context from what +narrow+ and tests pass: a Hash of
      # selections, a DependencyInjection, a context, or nil.
      def context_from(value)
        case value
        when DependencyInjectionContext then value
        when DependencyInjection then DependencyInjectionContext::EMPTY.with(value)
        when nil then DependencyInjectionContext::EMPTY
        when Hash then DependencyInjectionContext::EMPTY.with(DependencyInjection.new(value).freeze)
        else raise ArgumentError, "expected selections, got #{value.inspect}"
        end
      end

      # The selected requirements of +child_name+ of +model+ in +context+.
      def for_child(model, child_name, context)
        select(model.find_child(child_name), context).requirements
      end

      # What fills +child+ in +context+ (see Result); raises when the
      # selection does not fullfill what the child requires.
      def select(child, context)
        value, used = context.selected_value_for(child.child_name, child.models)
        explicit = used.include?(child.child_name)
        return Result.new(child.requirements, used, explicit, nil) if value.nil?
        return Result.new(child.requirements, used, explicit, value) if value.is_a?(Models::ChildReference)

        value = resolve_tag(value, context)
        location = context.location_of(used.first) || child.declared_at
        selected = InstanceRequirements.from(expand_placeholder(value), location: location)
        # Data services (or a placeholder of them) selected for a child add
        # to what it requires, as in Syskit (+narrow('pose' => Srv)+: a Pose
        # that also provides Srv).
        selected = selected.add_models(child.models, location: location) if services_only?(selected)
        selected = with_service_selected_by_model(selected, child, context)
        check_fullfills(child, selected, value, location)
        Result.new(child.requirements.merge_selection(selected), used, explicit, nil)
      end

      # A component selected by name without saying which of its services
      # fills the child takes the one the context selects for a data
      # service model the child requires (+'test' => Task, Srv =>
      # Task.x_srv+), as Syskit does.
      def with_service_selected_by_model(selected, child, context)
        component = selected.component_model
        return selected if selected.service || selected.instance || !component.is_a?(Class)

        child.models.grep(Models::DataServiceModel).each do |service_model|
          service = context.direct_selection_for(service_model)
          next unless service.is_a?(Models::BoundDataService) && service.component_model.equal?(component)

          return selected.select_service(service)
        end
        selected
      end

      # Whether +selected+ names data services only (no component, device
      # or task).
      def services_only?(selected)
        return false if selected.device || selected.instance || selected.models.empty?

        selected.models.all?(Models::DataServiceModel)
      end

      # A placeholder model selected stands for the models it was made of.
      def expand_placeholder(value)
        return value unless value.is_a?(Class) && value.placeholder?

        base = value.proxied_component_model
        value.proxied_data_service_models + (base.equal?(Syskit::Component) ? [] : [base])
      end

      # A tag selected by the profile's (or a using profile's) injection.
      def resolve_tag(value, context)
        return value unless value.is_a?(Actions::Profile::Tag)

        context.direct_selection_for(value) || value
      end

      def check_fullfills(child, selected, value, location)
        return if selected.abstract? && selected.models.empty?

        check_single_service(child, selected, value, location)
        missing = missing_models(child, selected)
        return if missing.empty?

        raise NetworkError.new(
          "#{value} is selected for #{child}, but it does not fullfill #{missing.join(', ')}",
          location: location,
          hint: "select a model that is or provides #{missing.join(' and ')} for '#{child.child_name}'"
        )
      end

      # What +child+ requires and +selected+ does not fullfill. A device
      # whose driver is not known yet is checked against task models once
      # it is (see Drivers#instantiate_device).
      def missing_models(child, selected)
        missing = child.models.reject { |m| selected.fullfills?(m) }
        pending = selected.device && !selected.device.driver_resolved?
        pending ? missing.grep_v(Class) : missing
      end

      # A component that provides a service the child requires more than
      # once must be told which one fills the child.
      def check_single_service(child, selected, value, location)
        model = selected.component_model
        return if selected.service || selected.device || !model.respond_to?(:services_fulfilling)

        child.models.grep(Models::DataServiceModel).each do |service_model|
          services = model.services_fulfilling(service_model).select(&:master?)
          next if services.size < 2

          names = services.map(&:name)
          raise NetworkError.new(
            "#{value} is selected for #{child}, but it provides #{service_model} several times " \
            "(#{names.join(', ')})",
            location: location,
            hint: "select one of them: '#{child.child_name}' => #{Naming.dsl_reference(model)}.#{names.first}_srv"
          )
        end
      end
    end
  end
end
