# frozen_string_literal: true

# The gem's language server (`syskit lsp`, see doc/guides/editor.md). The
# protocol's messages are read and written with the language_server-protocol
# gem, as Ruby's own language servers do; each query capability is a small
# class of its own, with no protocol code, answering on a loaded app.
require 'io/wait'
require 'language_server-protocol'
require 'syskit/check'
require 'syskit/lsp/uri'
require 'syskit/lsp/diagnostics'
require 'syskit/lsp/session'
require 'syskit/lsp/workspace'
require 'syskit/lsp/hover'
require 'syskit/lsp/definition'
require 'syskit/lsp/completion'
require 'syskit/lsp/document_symbols'
require 'syskit/lsp/queries'
require 'syskit/lsp/server'
