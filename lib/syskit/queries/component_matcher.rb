# frozen_string_literal: true

module Syskit
  module Queries
    # Finds components (task instances) of a plan by model and state
    # (+Task.match.abstract+), and narrows to their services and ports
    # (+Task.match.gps_srv+, +Task.match.out_port+). A component must
    # fullfill all the models given (+with_model([Task, Srv])+).
    class ComponentMatcher
      include PlanResults
      include Accessors

      def initialize
        @models = []
        @predicates = {}
        @arguments = {}
      end

      # Matches components that fullfill +models+ (one model or several).
      def with_model(models)
        @models = Array(models)
        define_accessors
        self
      end

      # Matches components with these arguments.
      def with_arguments(**arguments)
        @arguments = @arguments.merge(arguments)
        self
      end

      # Matches abstract components only.
      def abstract
        @predicates[:abstract?] = true
        self
      end

      # Matches components that are not abstract only.
      def not_abstract
        @predicates[:abstract?] = false
        self
      end

      # Matches running components only (Roby's +running+). A plan held as
      # data runs nothing: it finds none there, and its ports
      # (+Task.match.running.out_port+) name what a data_reader binds to
      # once Syskit's runtime runs the tasks.
      def running
        @running = true
        self
      end

      # A matcher is its own matcher (see PortMatcher.new).
      def match
        self
      end

      def ===(task)
        !@running && task.is_a?(AbstractComponent) &&
          @models.all? { |m| task.fullfills?(m) } &&
          @predicates.all? { |predicate, value| task.public_send(predicate) == value } &&
          @arguments.all? { |key, value| task.arguments[key] == value }
      end

      # Yields the tasks of +plan+ that match.
      def each_in_plan(plan, &block)
        return enum_for(__method__, plan) unless block

        plan.each { |task| yield(task) if self === task } # rubocop:disable Style/CaseEquality
      end
    end
  end
end
