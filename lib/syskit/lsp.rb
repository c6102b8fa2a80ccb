# frozen_string_literal: true

# The gem's language server (`syskit lsp`). The protocol's messages are read
# and written with the language_server-protocol gem, as Ruby's own language
# servers do.
require 'language_server-protocol'
require 'syskit/check'
require 'syskit/lsp/uri'
require 'syskit/lsp/diagnostics'
require 'syskit/lsp/session'
require 'syskit/lsp/workspace'
require 'syskit/lsp/queries'
require 'syskit/lsp/server'
