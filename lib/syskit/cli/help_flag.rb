# frozen_string_literal: true

require 'delegate'

module Syskit
  class CLI < Thor
    module Help
      # A boolean option as its help shows it: [--dry-run].
      class Flag < SimpleDelegator
        def usage(padding = 0)
          __getobj__.usage(padding).gsub(/, \[--(?:no|skip)-[\w-]+\]/, '')
        end
      end
    end
  end
end
