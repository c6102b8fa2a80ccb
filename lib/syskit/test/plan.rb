# frozen_string_literal: true

require 'set'

module Syskit
  module Test
    # The plan of Syskit's tests, as data: the task instances a test adds
    # (+plan.add(task = Cmp.new)+), which of them are missions or
    # permanent, and queries on them (+plan.find_tasks(Model).first+).
    # Nothing in it runs: Roby's execution of a plan is out of the gem's
    # scope (see RuntimeOnly).
    class Plan
      include Enumerable

      attr_reader :tasks, :mission_tasks, :permanent_tasks

      def initialize
        @tasks = Set.new
        @mission_tasks = Set.new
        @permanent_tasks = Set.new
      end

      # Adds +tasks+ (one task or several) and returns what was given.
      def add(tasks)
        Array(tasks).each { |task| @tasks << task }
        tasks
      end

      def add_mission_task(task)
        add(task)
        @mission_tasks << task
        task
      end

      def add_permanent_task(task)
        add(task)
        @permanent_tasks << task
        task
      end

      def unmark_mission_task(task)
        @mission_tasks.delete(task)
      end

      def unmark_permanent_task(task)
        @permanent_tasks.delete(task)
      end

      def mission_task?(task)
        @mission_tasks.include?(task)
      end

      def permanent_task?(task)
        @permanent_tasks.include?(task)
      end

      def remove_task(task)
        [@tasks, @mission_tasks, @permanent_tasks].each { |set| set.delete(task) }
        task
      end

      # Puts +new_task+ in the place of +task+: its mission and permanent
      # marks, its roles in the compositions it is a child of (whose
      # connections then map onto +new_task+'s ports), and its plan service
      # (see #replaced). +task+ leaves the plan.
      def replace_task(task, new_task)
        replace(task, new_task)
        @tasks.delete(task)
        new_task
      end

      # Roby's +plan.replace(task, new_task)+: as #replace_task, +task+
      # staying in the plan.
      def replace(task, new_task)
        add(new_task)
        @mission_tasks << new_task if @mission_tasks.delete?(task)
        @permanent_tasks << new_task if @permanent_tasks.delete?(task)
        parents = task.respond_to?(:each_parent_task) ? task.each_parent_task.to_a : []
        parents.each { |parent| parent.replace_child(task, new_task) }
        replaced(task, new_task)
      end

      # Roby's +plan.replaced(task, new_task)+: the plan service of +task+
      # (+task.as_service+) now stands for +new_task+.
      def replaced(task, new_task)
        task.plan_service&.replace(new_task)
        new_task
      end

      def include?(task)
        @tasks.include?(task)
      end

      def each(&)
        @tasks.each(&)
      end

      def empty?
        @tasks.empty?
      end

      def clear
        [@tasks, @mission_tasks, @permanent_tasks].each(&:clear)
      end

      # The tasks that are instances of +model+ (all without one), as a
      # query that can be narrowed further (+.with_arguments(id: 2)+).
      def find_tasks(model = nil)
        Query.new(@tasks.to_a).with_model(model)
      end
      alias find_local_tasks find_tasks

      # The answer of Plan#find_tasks: an enumerable of tasks.
      class Query
        include Enumerable

        def initialize(tasks)
          @tasks = tasks
        end

        def with_model(model)
          return self unless model

          Query.new(@tasks.select { |t| t.is_a?(model) || (t.respond_to?(:fullfills?) && t.fullfills?(model)) })
        end

        def with_arguments(**arguments)
          Query.new(@tasks.select { |t| arguments.all? { |key, value| t.arguments[key] == value } })
        end

        def each(&)
          @tasks.each(&)
        end
      end
    end
  end
end
