# frozen_string_literal: true

module Syskit
  class InstanceRequirements
    # What Syskit's requirements answer about the components that fill
    # them, and how two requirements combine: +fullfilled_model+, +merge+,
    # +merge_selection+, +bind+/+try_bind+. Part of InstanceRequirements.
    module Combination
      # Syskit's summary of what fills these requirements: [the component
      # model (Syskit::Component when only services are required), the
      # other models it must fullfill, the required arguments].
      def fullfilled_model
        others = fullfilled_models.reject { |m| m.is_a?(Class) && m <= Syskit::Component }
        [component_model || Syskit::Component, others | [Syskit::AbstractComponent], arguments]
      end

      # The requirements of both (Syskit's +merge+): the most specific
      # component model (IncompatibleComponentModels when neither derives
      # from the other) with the service models it does not provide, both
      # arguments and selections, the service either selects. Abstract
      # when both are, or either is with +keep_abstract+.
      def merge(other, keep_abstract: false)
        other = InstanceRequirements.from(other)
        _, combined, = DependencyInjection.new.selection_for(nil, InstanceRequirements.new(models + other.models))
        merged = merge_selection(other)
        abstract = keep_abstract ? abstract_flag || other.abstract_flag : abstract_flag && other.abstract_flag
        merged.send(:copy, models: combined.models, service: service || other.service,
                           arguments: arguments.merge(other.arguments), abstract: abstract)
      end

      # +task+ when it fills these requirements (a task of a model that
      # fullfills them all), else nil (Syskit's +try_bind+).
      def try_bind(task)
        task if task.respond_to?(:model) && !task.is_a?(Module) && task.model.fullfills?(models)
      end

      # As #try_bind, an ArgumentError when +task+ does not fill them.
      def bind(task)
        try_bind(task) ||
          raise(DeclarationError.new("#{Arguments.shown(task)} does not fill #{self}",
                                     location: Location.of_caller, hint: "give a task that is a #{self}"))
      end

      # A task standing for these requirements in a plan, to be planned
      # (Syskit's +as_plan+): a task of the model, with +arguments+, whose
      # +planning_task+ holds the requirements (+job_id+ stays there).
      def as_plan(**arguments)
        job_id = arguments.delete(:job_id)
        requirements = dup.with_arguments(**arguments)
        task = proxy_model.new(requirements.arguments)
        task.requirements = requirements
        task.planning_task = InstanceRequirementsTask.new(requirements, job_id: job_id)
        task
      end

      # Merges +other+ (a selection for a child) over these requirements (the
      # child's own): the selection's models, device and service, its
      # arguments, sections and hints when it gives some, both injections
      # and deployment groups.
      def merge_selection(other)
        InstanceRequirements.new(
          other.raw_models,
          device: other.device, service: other.service, profile: other.profile, name: other.name,
          arguments: other.arguments.empty? ? arguments : other.arguments,
          conf: other.conf_given? ? other.conf : @conf,
          conf_location: other.conf_given? ? other.conf_location : conf_location,
          deployment_hints: merged_hints(other), deployment: other.deployment || deployment,
          selections: merged_selections(other), deployment_group: merged_deployment_group(other),
          specialization_hints: specialization_hints + other.specialization_hints,
          declared_at: other.declared_at || declared_at, instance: other.instance,
          port_dynamics: port_dynamics.merge(other.port_dynamics)
        )
      end

      # These requirements as an action (see Actions::Models::Action).
      def to_action_model(doc = nil)
        Actions::Models::Action.new(self, doc)
      end

      protected

      def abstract_flag
        @abstract
      end

      def raw_hints
        @deployment_hints
      end

      def raw_models
        @models
      end

      def raw_deployment_group
        @deployment_group
      end

      private

      def merged_hints(other)
        other.raw_hints.empty? ? @deployment_hints : other.raw_hints
      end

      def merged_deployment_group(other)
        theirs = other.raw_deployment_group
        return @deployment_group if theirs.nil? || theirs.empty?
        return theirs if @deployment_group.nil? || @deployment_group.empty?

        @deployment_group.dup.use_group(theirs)
      end

      def merged_selections(other)
        return selections if other.selections.empty?
        return other.selections if selections.empty?

        DependencyInjection.of(selections.explicit.merge(other.selections.explicit),
                               selections.defaults | other.selections.defaults, other.selections.declared_at)
      end
    end
  end
end
