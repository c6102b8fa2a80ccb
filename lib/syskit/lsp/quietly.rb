# frozen_string_literal: true

module Syskit
  # The language server's queries (see lib/syskit/lsp.rb).
  module LSP
    # Runs the block with Ruby's warnings off: Ripper prints the parser's
    # warnings (a regexp with a bare ']') on stderr, which a language
    # server's client shows as noise, for every line it lexes.
    def self.quietly
      verbose = $VERBOSE
      $VERBOSE = nil
      yield
    ensure
      $VERBOSE = verbose
    end
  end
end
