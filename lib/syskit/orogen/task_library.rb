# frozen_string_literal: true

module Syskit
  module Orogen
    # A loaded task library (an oroGen project): its task models and
    # deployments, reachable as +OroGen.<name>+.
    class TaskLibrary
      attr_reader :name, :path, :tasks, :deployments, :namespace

      def initialize(name, path)
        @name = name
        @path = path
        @tasks = {}
        @deployments = {}
        @namespace = Syskit::Namespace.new('OroGen', [name])
      end

      def add_task(model)
        @tasks[model.name] = model
        @namespace.add(model.name.delete_prefix("#{name}::").split('::'), model)
      end

      # A task model by full (+canbus::Task+) or library-relative (+Task+) name.
      def find_task(task_name)
        tasks[task_name] || tasks["#{name}::#{task_name}"]
      end

      def to_s
        name
      end
    end
  end
end
