# frozen_string_literal: true

require 'json'

module Syskit
  module Render
    # The plan as a JSON document, for programs. Same plan, same bytes.
    module JSON
      module_function

      def render(plan)
        "#{::JSON.pretty_generate(plan.to_h)}\n"
      end
    end
  end
end
