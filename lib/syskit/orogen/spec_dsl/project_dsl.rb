# frozen_string_literal: true

module Syskit
  module Orogen
    # Top-level statements of an .orogen file.
    class ProjectDSL
      include StatementsDSL

      # C++ class names, in namespaces or not (Task, test::Replay).
      TASK_NAME = /\A[A-Za-z_]\w*(?:::[A-Za-z_]\w*)*\z/
      # Deployments name executables: letters, digits, _ and -.
      DEPLOYMENT_NAME = /\A[A-Za-z0-9_][A-Za-z0-9_-]*\z/

      def initialize(loader)
        @loader = loader
      end

      def dsl_context
        'an .orogen file'
      end

      def name(project_name)
        @loader.check_project_name(project_name.to_s, Location.of_caller)
      end

      def task_context(task_name = nil, subclasses: nil, **_options, &block)
        task_name = Arguments.name(task_name, statement: 'task_context', what: 'a task name (a C++ class name)',
                                              example: "task_context 'Task' do ... end", pattern: TASK_NAME,
                                              rule: 'letters, digits and _, not starting with a digit, ' \
                                                    'in namespaces or not (test::Replay)',
                                              error_class: SpecError)
        @loader.define_task(task_name, subclasses&.to_s, Location.of_caller, &block)
      end

      def deployment(deployment_name = nil, &)
        deployment_name = Arguments.name(deployment_name, statement: 'deployment', what: 'a deployment name',
                                                          example: "deployment 'test_gps' do ... end",
                                                          pattern: DEPLOYMENT_NAME, error_class: SpecError)
        @loader.define_deployment(deployment_name, Location.of_caller, &)
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

      # oroGen's ROS integration: not modelled, with a warning.
      %i[ros_node ros_launcher].each do |statement|
        define_method(statement) do |*_args, **_options, &_block|
          Syskit.app&.not_modelled(statement.to_s, Location.of_caller)
          Compat::Ignored.instance
        end
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
         export_types orogen_version default_task_context_superclass global_scope
         define_default_deployments= type_export_policy add_definitions].each do |statement|
        define_method(statement) { |*_args, **_options, &_block| nil }
      end
    end
  end
end
