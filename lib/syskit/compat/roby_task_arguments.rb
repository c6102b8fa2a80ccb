# frozen_string_literal: true

module Syskit
  module Compat
    module Roby
      # A task's arguments, as Roby's +task.arguments+: a hash that also
      # says which arguments are set (+set?(:speed)+), a delayed argument
      # (+from(:parent_task).speed+) being not set yet.
      class TaskArguments < Hash
        def set?(key)
          key?(key) && !self[key].is_a?(DelayedArgument)
        end
      end
    end
  end
end
