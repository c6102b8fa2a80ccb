# frozen_string_literal: true

module Syskit
  module Compat
    module Roby
      # Roby's plan service (+task.as_service+): a handle on a task of the
      # plan that follows the replacements of that task (when a network is
      # stubbed, see Test::Plan#replaced), so a test keeps track of it.
      class PlanService
        def initialize(task)
          @task = task
        end

        # The task the service stands for now.
        def to_task
          @task
        end
        alias task to_task

        # The service now stands for +task+, which replaced its task.
        def replace(task)
          @task = task
          task.plan_service = self
        end
      end
    end
  end
end
