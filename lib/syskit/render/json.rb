# frozen_string_literal: true

module Syskit
  module Render
    # The plan as a JSON document, for programs. Same plan, same bytes.
    module JSON
      module_function

      # json is required here, not at start-up: it adds Kernel#j and #jj,
      # which user files could then call by mistake.
      def render(plan)
        require 'json'
        "#{::JSON.pretty_generate(plan.to_h)}\n"
      end
    end
  end
end
