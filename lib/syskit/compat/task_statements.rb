# frozen_string_literal: true

module Syskit
  module Compat
    # Statements of real extension files about what a running component
    # does (the transformer's frames, polling, event handlers, scripts):
    # accepted in task model bodies, with a "not modelled" warning each.
    module TaskStatements
      RUNTIME_STATEMENTS = %i[poll on script event terminates forward signal stream_aligner on_exception].freeze

      RUNTIME_STATEMENTS.each do |statement|
        define_method(statement) do |*_args, **_options, &_block|
          Syskit.app&.not_modelled("#{statement} in #{name}", Location.of_caller)
          Compat::Ignored.instance
        end
      end

      # Frames and transformations given in Ruby (Syskit's transformer
      # extension) are runtime. Without a block, a task model answers what
      # its .orogen file declares (Models::TaskContext#transformer).
      def transformer(*_args, **_options, &block)
        return super() if block.nil? && defined?(super)

        Syskit.app&.not_modelled("transformer in #{name}", Location.of_caller)
        Compat::Ignored.instance
      end

      # Roby's delayed arguments (see DelayedArgument): a composition's
      # +from(:parent_task)+ is modelled, the others (the planning task,
      # the state) are runtime.
      def from(object)
        Syskit.app&.not_modelled("from in #{name}", Location.of_caller) unless object == :parent_task
        DelayedArgument.new(object)
      end
    end
  end
end
