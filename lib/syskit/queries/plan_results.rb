# frozen_string_literal: true

module Syskit
  module Queries
    # What every matcher finds in a plan, as a list or a set, from its
    # +each_in_plan+.
    module PlanResults
      def to_a(plan)
        each_in_plan(plan).to_a
      end

      def to_set(plan)
        each_in_plan(plan).to_set
      end
    end
  end
end
