# frozen_string_literal: true

module Syskit
  module Queries
    # Finds the ports of what a component or service matcher finds, by
    # name (a string or a pattern) and type.
    class PortMatcher
      include PlanResults

      # +component_matcher+ is a matcher, or a model (its +match+ is used).
      def initialize(component_matcher)
        @component_matcher = component_matcher.match
        @name_filter = nil
        @type_filter = nil
      end

      # Matches the ports of this name (a String), or whose name matches
      # this pattern (a Regexp).
      def with_name(name)
        @name_filter = name
        self
      end

      # Matches the ports of this type.
      def with_type(type)
        @type_filter = type
        self
      end

      # The type of the matched ports, when it is known without a plan:
      # the type filter, or the type of the port an exact name designates.
      def try_resolve_type
        return @type_filter if @type_filter

        resolve_port&.type
      end

      # The direction (:input or :output) of the port an exact name
      # designates; nil when not known.
      def try_resolve_direction
        return unless (port = resolve_port)

        port.output? ? :output : :input
      end

      def ===(port)
        port.is_a?(Port) &&
          (!@name_filter || @name_filter === port.name) && # rubocop:disable Style/CaseEquality
          (!@type_filter || @type_filter == port.type) &&
          @component_matcher === port.component # rubocop:disable Style/CaseEquality
      end

      # Yields the matching ports of what the component matcher finds in +plan+.
      def each_in_plan(plan)
        return enum_for(__method__, plan) unless block_given?

        @component_matcher.each_in_plan(plan) do |component|
          component.each_port { |port| yield(port) if self === port } # rubocop:disable Style/CaseEquality
        end
      end

      private

      def resolve_port
        return unless @name_filter.respond_to?(:to_str)

        @component_matcher.find_port_by_name(@name_filter)
      rescue Ambiguous
        nil
      end
    end
  end
end
