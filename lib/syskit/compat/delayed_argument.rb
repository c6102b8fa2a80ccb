# frozen_string_literal: true

module Syskit
  module Compat
    # Roby's delayed arguments, as compositions write them to pass their
    # own arguments down to a child:
    #
    #   add(Generator, as: 'command').with_arguments(setpoint: from(:parent_task).setpoint)
    #
    # The generator resolves it from the composition the child is
    # instantiated in: its argument of that name (or the result of the
    # calls that follow, on it). Where the parent does not have it, the
    # child's argument stays unset, as in Roby until the parent gets it.
    class DelayedArgument
      # What #resolve gives when the value is not there.
      UNSET = Object.new.freeze

      attr_reader :object, :calls

      def initialize(object, calls = [])
        @object = object
        @calls = calls.freeze
        freeze
      end

      # Roby's type filter on a delayed argument: no effect here.
      FILTERS = %i[of_type].freeze

      # The value for a child of +parent+ (a composition task), or UNSET.
      def resolve(parent)
        names = calls.filter_map { |name, _| name unless FILTERS.include?(name) }
        return UNSET unless object == :parent_task && parent && !names.empty?

        first, *rest = names
        return UNSET unless parent.arguments.key?(first)

        rest.reduce(parent.arguments[first]) { |value, call| value.public_send(call) }
      end

      def to_s
        "from(#{object.inspect})#{calls.map do |name, args|
          ".#{name}#{"(#{args.join(', ')})" unless args.empty?}"
        end.join}"
      end
      alias inspect to_s

      private

      # Any call records its name (and arguments): +from(:parent_task).robot+.
      def method_missing(name, *args, &)
        return super if Ignored::CONVERSIONS.include?(name)

        DelayedArgument.new(object, calls + [[name, args]])
      end

      def respond_to_missing?(name, include_private = false)
        !Ignored::CONVERSIONS.include?(name) || super
      end
    end
  end
end
