# frozen_string_literal: true

module Syskit
  module Models
    # Statements of component models that give their requirements, as
    # Syskit's tests and profiles write them:
    # +OroGen.lib.Task.with_conf('default', 'x').with_arguments(port: 'p')+
    # (see InstanceRequirements).
    module TaskRequirementStatements
      %i[with_conf with_arguments deployed_as deployed_as_unmanaged prefer_deployed_tasks with_dynamic_service
         use_frames use_conf use_deployment use_unmanaged_task use_deployment_group].each do |statement|
        define_method(statement) do |*args, **options|
          InstanceRequirements.new([self], declared_at: Location.of_caller).public_send(statement, *args, **options)
        end
      end

      # Syskit's +Model.instanciate(plan, context)+: see
      # InstanceRequirements#instanciate.
      def instanciate(plan, context = DependencyInjectionContext::EMPTY, **options)
        to_instance_requirements.instanciate(plan, context, **options)
      end

      # A task of the model standing for it in a plan, to be planned
      # (Roby's +Model.as_plan+): see InstanceRequirements#as_plan.
      def as_plan(**arguments)
        to_instance_requirements.as_plan(**arguments)
      end

      # The model (a component or service model, or a component model's
      # service) as requirements (see InstanceRequirements).
      def to_instance_requirements
        InstanceRequirements.from(self, location: Location.of_caller)
      end
    end
  end
end
