# frozen_string_literal: true

require 'delegate'

module Syskit
  class CLI < Thor
    # How syskit's commands describe themselves (extended by `syskit`,
    # `syskit gen` and `syskit bus`): without Thor's own `tree` command,
    # and flags without the --no-/--skip- forms Thor adds to them.
    module Help
      def printable_commands(all = true, subcommand = false) # rubocop:disable Style/OptionalBooleanParameter -- Thor's signature
        super.reject { |usage, _| usage.match?(/\A\S+(?: \S+)? tree\z/) }
      end

      def print_options(shell, options, group_name = nil)
        super(shell, options.map { |option| option.boolean? ? Flag.new(option) : option }, group_name)
      end

      # A boolean option as its help shows it: [--dry-run].
      class Flag < SimpleDelegator
        def usage(padding = 0)
          __getobj__.usage(padding).gsub(/, \[--(?:no|skip)-[\w-]+\]/, '')
        end
      end
    end
  end
end
