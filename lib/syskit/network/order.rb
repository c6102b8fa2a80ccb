# frozen_string_literal: true

module Syskit
  module Network
    # Step 4: the order in which tasks are configured and started. A task is
    # configured once the buses it is attached through are started; tasks of
    # the same rank are ordered by name, so the order is stable.
    class Order
      # One step of the order: 'configure' or 'start' a task.
      Step = Struct.new(:step, :task, :rank)

      def initialize(context)
        @context = context
        @ranks = {}.compare_by_identity
        @visiting = {}.compare_by_identity
      end

      # Steps are put in one bucket per rank, tasks taken in name order, so
      # no sort is needed (configure ranks are even, start ranks odd).
      def run
        buckets = []
        @context.tasks_by_name.each do |task|
          rank = configure_rank(task)
          (buckets[rank] ||= []) << Step.new('configure', task, rank)
          (buckets[rank + 1] ||= []) << Step.new('start', task, rank + 1)
        end
        @context.order = buckets.compact.flatten(1)
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
