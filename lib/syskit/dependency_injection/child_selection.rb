# frozen_string_literal: true

module Syskit
  class DependencyInjection
    # What an injection selects for one child (Syskit's +selection_for+):
    # by its name first, else model by model. Part of DependencyInjection.
    module ChildSelection
      # What is selected for the child +name+ (nil for none) that must
      # fullfill +requirements+ (requirements, or what stands for them):
      # [the task selected, if a task is; the selected requirements;
      # { required service model => the service that fills it }; the keys
      # used]. IncompatibleComponentModels when selections for different
      # models give unrelated component models.
      def selection_for(name, requirements)
        return resolve.selection_for(name, requirements) unless defaults.empty?

        requirements = InstanceRequirements.from(requirements)
        picks, services, used = picks_for(name, requirements)
        instance = selected_instance(picks, requirements)
        selected = combined_requirements(picks, requirements, services)
        [instance, selected, services, used]
      end

      # #selection_for as Syskit's +instance_selection_for+: [an
      # InstanceSelection, the keys used].
      def instance_selection_for(name, requirements)
        instance, selected, services, used = selection_for(name, requirements)
        [InstanceSelection.new(instance, selected, InstanceRequirements.from(requirements), services), used]
      end

      private

      # The selected values, each with the model it is selected for (nil
      # when selected by name), the services selected by name, the keys used.
      def picks_for(name, requirements)
        by_name = name && explicit[name]
        services = {}
        if by_name && !by_name.equal?(DO_NOT_INHERIT)
          by_name = requirements if by_name.equal?(NOTHING)
          services_selected_with(by_name, requirements, services)
          return [[[by_name, nil]], services, Set[name]]
        end

        used = Set.new
        picks = requirements.models.map do |required|
          value = explicit[required]
          next [required, required] if value.nil? || DependencyInjection.placeholder?(value)

          used << required
          [value, required]
        end
        [picks, services, used]
      end

      # The services selected for models (+Srv => Task.x_srv+) on the
      # component model selected by name: they fill the required models
      # their key fullfills.
      def services_selected_with(selected, requirements, services)
        explicit.each do |key, value|
          next unless value.is_a?(Models::BoundDataService) && value.component_model.equal?(selected)

          requirements.models.each do |required|
            services[required] ||= value if key.respond_to?(:fullfills?) && key.fullfills?(required)
          end
        end
      end

      # The one task instance selected, if any (an ArgumentError when two
      # are, or when it does not fullfill the requirements).
      def selected_instance(picks, requirements)
        tasks = picks.filter_map { |value, _| instance_of(value) }.uniq
        if tasks.size > 1
          raise DeclarationError.new("#{tasks.join(' and ')} are both selected for #{requirements}",
                                     location: declared_at, hint: 'select one task')
        end

        task = tasks.first
        return task if task.nil? || task.model.fullfills?(requirements.models)

        raise DeclarationError.new("#{task} is selected, but it does not fullfill #{requirements}",
                                   location: declared_at, hint: "select a task that is a #{requirements}")
      end

      def instance_of(value)
        case value
        when Syskit::BoundDataService then value.component
        when AbstractComponent then value
        end
      end

      # The requirements the picks give together: their component models
      # (the most specific one; IncompatibleComponentModels when they are
      # unrelated), the service models no component fills. Fills
      # +services+ with the services the picks select.
      def combined_requirements(picks, requirements, services)
        component = nil
        service_models = []
        first = nil
        picks.each do |value, required|
          selected = InstanceRequirements.from(value)
          first ||= selected
          record_service(selected.service, required, requirements, services) if selected.service
          selected.models.each do |m|
            m.is_a?(Class) ? component = most_specific(component, m) : service_models << m
          end
        end
        models = [component, *service_models.uniq.reject { |m| component&.fullfills?(m) }].compact
        base = picks.size == 1 ? first : InstanceRequirements.new
        base.with_models(models)
      end

      def record_service(service, required, requirements, services)
        return services[required] = service if required

        requirements.models.each { |m| services[m] ||= service if service.fullfills?(m) }
      end

      def most_specific(current, model)
        return model if current.nil? || model <= current
        return current if current <= model

        raise IncompatibleComponentModels.new("#{current} and #{model} are both selected, and neither is the other",
                                              location: declared_at, hint: 'select models that derive one from another')
      end
    end
  end
end
