# frozen_string_literal: true

module Syskit
  module Models
    # A task model with what is asked of it, as Syskit's tests and profiles
    # write it: +OroGen.lib.Task.with_conf('default', 'x').with_arguments(port: 'p')+.
    # syskit_stub_deploy_and_configure takes one. Each call returns a copy.
    class TaskRequirements
      attr_reader :model, :conf, :arguments, :deployment, :deployment_hints

      def initialize(model, conf: nil, arguments: {}, deployment: nil, deployment_hints: [])
        @model = model
        @conf = conf
        @arguments = arguments.freeze
        @deployment = deployment
        @deployment_hints = deployment_hints.freeze
        freeze
      end

      # Configuration sections, replacing ['default'] as in Syskit.
      def with_conf(*names)
        copy(conf: names.flatten.map(&:to_s).freeze)
      end

      # Task arguments (see TaskModel#argument).
      def with_arguments(**arguments)
        copy(arguments: self.arguments.merge(arguments))
      end

      # A deployment of its own. Stub deployments (syskit_stub_*) ignore it,
      # as Syskit's do.
      def deployed_as(name)
        copy(deployment: name.to_s)
      end
      alias deployed_as_unmanaged deployed_as

      def prefer_deployed_tasks(*hints)
        copy(deployment_hints: deployment_hints + hints.flatten)
      end

      def to_s
        parts = []
        parts << "with_conf(#{conf.map(&:inspect).join(', ')})" if conf
        parts << "with_arguments(#{arguments.map { |k, v| "#{k}: #{v.inspect}" }.join(', ')})" unless arguments.empty?
        [model.name, *parts].join('.')
      end
      alias inspect to_s

      private

      def copy(**changes)
        TaskRequirements.new(model, conf: conf, arguments: arguments, deployment: deployment,
                                    deployment_hints: deployment_hints, **changes)
      end
    end

    # Statements of task models that give their requirements.
    module TaskRequirementStatements
      %i[with_conf with_arguments deployed_as deployed_as_unmanaged prefer_deployed_tasks].each do |statement|
        define_method(statement) do |*args, **options|
          TaskRequirements.new(self).public_send(statement, *args, **options)
        end
      end
    end
  end
end
