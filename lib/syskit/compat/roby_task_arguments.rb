# frozen_string_literal: true

module Syskit
  module Compat
    module Roby
      # Roby's default argument: a value a task takes for an argument
      # unless it gets another. It does not count as set, and a task that
      # is merged gives it only to a task without that argument at all.
      class DefaultArgument
        attr_reader :value

        def initialize(value)
          @value = value
          freeze
        end

        def ==(other)
          other.is_a?(DefaultArgument) && other.value == value
        end
        alias eql? ==

        def hash
          [DefaultArgument, value].hash
        end

        def to_s
          "default(#{value.inspect})"
        end
        alias inspect to_s
      end

      # A task's arguments, as Roby's +task.arguments+: a hash that also
      # says which arguments are set (+set?(:speed)+), a delayed argument
      # (+from(:parent_task).speed+) or a default one being not set yet.
      class TaskArguments < Hash
        def set?(key)
          key?(key) && !self[key].is_a?(DelayedArgument) && !self[key].is_a?(DefaultArgument)
        end

        # Roby's +arguments.values+: the arguments by name, delayed and
        # default ones included (this hash itself).
        def values
          self
        end

        # Roby's +arguments.each_assigned_argument+: the arguments that are
        # set (see #set?), as name and value (an Enumerator without block).
        def each_assigned_argument
          return enum_for(__method__) unless block_given?

          each { |key, value| yield(key, value) if set?(key) }
        end
      end
    end
  end
end
