# frozen_string_literal: true

module Syskit
  # What plans a task in Syskit's plans (+InstanceRequirements#as_plan+):
  # the requirements the network generator will make the task from, and
  # the job it belongs to. Here a value the task carries as its
  # +planning_task+; running it (generating and deploying the network
  # when the plan executes) is Roby's runtime.
  class InstanceRequirementsTask
    attr_reader :requirements, :job_id

    def initialize(requirements, job_id: nil)
      @requirements = requirements
      @job_id = job_id
      freeze
    end

    def to_s
      "planning #{requirements}"
    end
    alias inspect to_s
  end
end
