# frozen_string_literal: true

module Syskit
  class CLI < Thor
    # A list of commands as `syskit help` prints it: usages in a column,
    # descriptions after '# ' wrapped at word boundaries to the terminal's
    # width (Thor cuts them mid-word). A usage longer than USAGE_COLUMN has
    # its description on the next line, so it does not squeeze the others.
    module CommandTable
      USAGE_COLUMN = 40
      # Descriptions get at least this many columns, whatever the width.
      MIN_ROOM = 30

      module_function

      # The lines of +rows+ ([usage, '# description'] pairs).
      def lines(rows, indent:, width:)
        column = rows.map { |usage, _| usage.size }.select { |size| size <= USAGE_COLUMN }.max.to_i + 2
        room = [width - indent - column - 2, MIN_ROOM].max
        rows.flat_map do |usage, description|
          row_lines(usage, description, column, room).map { |line| (' ' * indent) + line }
        end
      end

      def row_lines(usage, description, column, room)
        first, *rest = wrap(description.delete_prefix('# '), room)
        text = ["# #{first}", *rest.map { |line| "  #{line}" }]
        text.unshift('') if usage.size > USAGE_COLUMN
        ["#{usage.ljust(column)}#{text.shift}".rstrip, *text.map { |line| (' ' * column) + line }]
      end

      # +text+ in lines of at most +width+ characters, broken between words
      # (a longer word stands alone on its line).
      def wrap(text, width)
        text.split.each_with_object([+'']) do |word, lines|
          if lines.last.empty? then lines.last << word
          elsif lines.last.size + 1 + word.size <= width then lines.last << ' ' << word
          else lines << word.dup
          end
        end
      end
    end
  end
end
