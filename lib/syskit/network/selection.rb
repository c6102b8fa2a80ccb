# frozen_string_literal: true

module Syskit
  module Network
    # What fills a composition's child, from the dependency injection in
    # effect (see DependencyInjection::Context): one function of (child,
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
        when DependencyInjection::Context then value
        when DependencyInjection then DependencyInjection::Context::EMPTY.push(value)
        when nil then DependencyInjection::Context::EMPTY
        when Hash then DependencyInjection::Context::EMPTY.push(DependencyInjection::EMPTY.add([value], nil))
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
        value, used = context.selection_for(child.child_name, child.models)
        explicit = used.include?(child.child_name)
        return Result.new(child.requirements, used, explicit, nil) if value.nil?
        return Result.new(child.requirements, used, explicit, value) if value.is_a?(Models::CompositionChild)

        value = resolve_tag(value, context)
        location = context.location_of(used.first) || child.declared_at
        selected = InstanceRequirements.from(value, location: location)
        check_fullfills(child, selected, value, location)
        Result.new(child.requirements.merge_selection(selected), used, explicit, nil)
      end

      # A tag selected by the profile's (or a using profile's) injection.
      def resolve_tag(value, context)
        return value unless value.is_a?(Profile::Tag)

        context.direct_selection_for(value) || value
      end

      def check_fullfills(child, selected, value, location)
        return if selected.abstract? && selected.models.empty?

        check_single_service(child, selected, value, location)
        missing = child.models.reject { |m| selected.fullfills?(m) }
        return if missing.empty?
        return if selected.device && !selected.device.driver_resolved? &&
                  missing.all? { |m| m.is_a?(Class) } # checked once the driver is known

        raise NetworkError.new(
          "#{value} is selected for #{child}, but it does not fullfill #{missing.map(&:to_s).join(', ')}",
          location: location,
          hint: "select a model that is or provides #{missing.map(&:to_s).join(' and ')} for '#{child.child_name}'"
        )
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
