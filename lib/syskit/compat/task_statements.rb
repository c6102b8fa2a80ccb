# frozen_string_literal: true

module Syskit
  module Compat
    # Statements of real extension files about what a running component
    # does (the transformer's frames, polling, event handlers, scripts):
    # accepted in task model bodies, with a "not modelled" warning each.
    module TaskStatements
      RUNTIME_STATEMENTS = %i[transformer poll on script event terminates forward signal
                              stream_aligner on_exception from].freeze

      RUNTIME_STATEMENTS.each do |statement|
        define_method(statement) do |*_args, **_options, &_block|
          Syskit.app&.not_modelled("#{statement} in #{name}", Location.of_caller)
          Compat::Ignored.instance
        end
      end
    end
  end
end
