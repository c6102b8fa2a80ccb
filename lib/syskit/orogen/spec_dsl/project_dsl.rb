# frozen_string_literal: true

module Syskit
  module Orogen
    # Top-level statements of an .orogen file.
    class ProjectDSL
      include StatementsDSL

      def initialize(loader)
        @loader = loader
      end

      def dsl_context
        'an .orogen file'
      end

      def name(project_name)
        @loader.check_project_name(project_name.to_s, Location.of_caller)
      end

      def task_context(task_name, subclasses: nil, **_options, &block)
        @loader.define_task(task_name.to_s, subclasses, Location.of_caller, &block)
      end

      def deployment(deployment_name, &)
        @loader.define_deployment(deployment_name.to_s, Location.of_caller, &)
      end

      def static_deployment(&block)
        DeploymentDSL.new(@loader, DeploymentSpec.new('static')).instance_eval(&block) if block
      end

      def import_types_from(typekit_or_header, *_args, **_options)
        @loader.import_types(typekit_or_header.to_s, Location.of_caller)
      end

      def using_task_library(library_name, **_options)
        @loader.using_task_library(library_name.to_s, Location.of_caller)
      end

      def corba_enabled?
        true
      end

      # oroGen's +simple_deployment('name', 'Task')+: a deployment of one
      # task, both called +name+.
      def simple_deployment(deployment_name, model_name, &)
        deployment_name = deployment_name.to_s
        model_name = model_name.to_s
        location = Location.of_caller
        @loader.define_deployment(deployment_name, location) do
          task(deployment_name, model_name)
        end
        DeploymentDSL::DeployedTaskDSL.new
      end

      # +typekit do ... end+ or +typekit.export_types ...+ (see TypekitDSL).
      def typekit(&block)
        @loader.own_typekit
        dsl = TypekitDSL.new(@loader)
        dsl.instance_eval(&block) if block
        dsl
      end

      # Build-level statements: accepted, meaningless for planning.
      %i[version using_library using_typekit enable_namespace max_sizes cxx_standard
         export_types orogen_version default_task_context_superclass global_scope].each do |statement|
        define_method(statement) { |*_args, **_options, &_block| nil }
      end
    end
  end
end
