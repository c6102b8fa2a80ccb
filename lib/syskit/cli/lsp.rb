# frozen_string_literal: true

module Syskit
  # `syskit lsp`, a command of `syskit` (see syskit/cli.rb): the language
  # server editors start (see doc/guides/editor.md).
  class CLI < Thor
    desc 'lsp', "the Language Server Protocol on stdin/stdout, for editors: the check's problems as you type, " \
                'hover, go to definition, completion and symbols'
    long_desc <<~TEXT
      Editors start it and talk to it; it serves the app containing each
      file they open (the closest parent directory that is an app).
      See doc/guides/editor.md for the configuration of Neovim, Emacs
      (eglot) and VS Code.

      Its log (errors of syskit itself, and whatever the app's files
      print) goes to stderr, which editors keep as the server's log.
    TEXT
    def lsp
      if $stdin.tty?
        warn 'syskit lsp speaks the Language Server Protocol on stdin/stdout: editors start it ' \
             '(see doc/guides/editor.md). Ctrl-D ends it.'
      end
      # stdout is the protocol's: what the app's files (or anything they
      # run) print goes to stderr instead, and nothing they do reads the
      # protocol's input.
      input = $stdin.dup
      output = $stdout.dup
      $stdout.reopen($stderr)
      $stdin.reopen(File::NULL)
      exit(LSP::Server.new(input, output, log: $stderr).run)
    end
  end
end
