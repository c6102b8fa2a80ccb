# frozen_string_literal: true

module Syskit
  module Models
    class DeploymentGroup
      # The deployed tasks that can run a task of a model (their model is
      # it or a subclass of it), computed once per model: indexed by name
      # for prefer_deployed_tasks('name'), listed by name when they must be
      # scanned (regexp hints) or shown (errors).
      class Candidates
        attr_reader :by_name

        def initialize(groups)
          @by_name = {}
          groups.each { |tasks| tasks.each { |t| @by_name[t.name] = t } }
        end

        def empty?
          by_name.empty?
        end

        def list
          @list ||= by_name.values.sort_by(&:name).freeze
        end
      end

      # A deployed task as Syskit's group lists it: the deployment that
      # runs it and the task's name in it.
      DeployedTask = Struct.new(:configured_deployment, :mapped_task_name)

      # How a group finds the deployed tasks that can run a task. The
      # lookups are kept in a table of their own (+@lookups+, emptied when
      # the group changes), so that a frozen group, as frozen requirements
      # hold, still computes them. Part of DeploymentGroup.
      module Lookups
        # The Candidates for a task of +model+.
        def candidates_for(model)
          @lookups[model] ||= begin
            by_model = (@lookups[:by_model] ||= deployed_tasks.group_by(&:model))
            Candidates.new(by_model.filter_map { |m, tasks| tasks if m <= model })
          end
        end

        # Deployed tasks whose model is +model+ or a subclass of it, by name.
        def deployed_tasks_for(model)
          candidates_for(model).list
        end

        # The deployed tasks that can run +task+ (those of its concrete
        # model, see #candidates_for), as DeployedTask (Syskit's).
        def find_all_suitable_deployments_for(task)
          deployed_tasks_for(task.concrete_model).map { |t| DeployedTask.new(t.deployment, t.name) }
        end
      end
    end
  end
end
