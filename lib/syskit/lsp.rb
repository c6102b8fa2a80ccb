# frozen_string_literal: true

# The language server's queries on a loaded app (see doc/guides/editor.md):
# each capability a small class of its own, with no protocol code.
require 'syskit/lsp/hover'
require 'syskit/lsp/definition'
require 'syskit/lsp/completion'
require 'syskit/lsp/document_symbols'
