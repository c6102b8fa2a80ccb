# frozen_string_literal: true

module Syskit
  module Network
    # Step 4: the order in which tasks are configured and started. A task is
    # configured once the buses it is attached through are started; tasks of
    # the same rank are ordered by name, so the order is stable.
    class Order
      def initialize(context)
        @context = context
        @ranks = {}.compare_by_identity
        @visiting = {}.compare_by_identity
      end

      # Steps are put in one bucket per rank, tasks taken in name order, so
      # no sort is needed (configure ranks are even, start ranks odd). The
      # steps are made as the plan lists them (Plan::Step, by task name);
      # Configure takes the tasks in the order of their configure steps.
      def run
        steps = []
        configure = []
        @context.tasks_by_name.each do |task|
          rank = configure_rank(task)
          (steps[rank] ||= []) << Plan::Step.new('configure', task.name).freeze
          (steps[rank + 1] ||= []) << Plan::Step.new('start', task.name).freeze
          (configure[rank] ||= []) << task
        end
        @context.order = steps.compact.flatten(1).freeze
        @context.configure_order = configure.compact.flatten(1)
      end

      private

      # 0 for tasks without buses, else one more than the start of their buses.
      def configure_rank(task)
        return @ranks[task] if @ranks.key?(task)
        if @visiting.key?(task)
          raise NetworkError.new("tasks depend on each other: #{(@visiting.keys + [task]).map(&:name).join(' -> ')}",
                                 hint: 'a bus cannot be attached through itself')
        end

        @visiting[task] = true
        rank = 0
        task.children.each { |child| rank = [rank, configure_rank(child) + 2].max }
        @visiting.delete(task)
        @ranks[task] = rank
      end
    end
  end
end
