# frozen_string_literal: true

module Syskit
  class CLI < Thor
    # The terminal's width as Thor finds it, without its two processes:
    # Thor runs `stty size` then `tput cols` for every help it prints, which
    # takes longer (30-60 ms) than loading the whole command line. The same
    # answer from the same places: the window of standard input (stty), of
    # the output (tput), $COLUMNS (which tput reads), else 0, for which
    # Thor takes 80 columns. THOR_COLUMNS still comes first (Thor reads it).
    module TerminalWidth
      module_function

      def columns(ios = [$stdin, $stdout, $stderr], env = ENV)
        ios.each do |io|
          width = window_columns(io)
          return width if width.positive?
        end
        env['COLUMNS'].to_i
      end

      def window_columns(io)
        return 0 unless io.tty?

        require 'io/console'
        io.winsize.last
      rescue SystemCallError, IOError
        0
      end
    end
  end
end

# Thor's Terminal asks TerminalWidth instead of running stty and tput.
Thor::Shell::Terminal.singleton_class.prepend(Module.new do
  private

  def dynamic_width
    @dynamic_width ||= Syskit::CLI::TerminalWidth.columns
  end
end)
