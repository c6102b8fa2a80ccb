# frozen_string_literal: true

module Syskit
  class CLI < Thor
    # Colours of problem reports on a terminal: the location in bold, an
    # error's message in red, "warning:" in yellow, "hint:" in cyan. None
    # when the output is a pipe or a file, or when NO_COLOR is set
    # (https://no-color.org), so what scripts read never changes.
    class Style
      CODES = { bold: 1, red: 31, yellow: 33, cyan: 36 }.freeze

      def self.for(io, env = ENV)
        new(color: io.tty? && env.fetch('NO_COLOR', '').empty?)
      end

      def initialize(color:)
        @color = color
      end

      def color?
        @color
      end

      # +problem+'s report (Syskit::Error#report), coloured.
      def report(problem, root = nil)
        return problem.errors.map { |e| report(e, root) }.join("\n") if problem.is_a?(ErrorList)

        text = problem.report(root)
        return text unless @color

        first, *rest = text.lines
        [headline(first, problem.location&.to_s(root), problem.is_a?(Warning)),
         *rest.map { |line| line.sub(/\A(\s*)hint:/) { "#{Regexp.last_match(1)}#{paint('hint:', :cyan)}" } }].join
      end

      def warning(text)
        @color ? paint(text, :yellow) : text
      end

      private

      def headline(line, location, warning)
        line = line.dup
        prefix = location && line.start_with?("#{location}: ") ? "#{paint(location, :bold)}: " : ''
        line = line.delete_prefix("#{location}: ") unless prefix.empty?
        body = if warning
                 line.sub(/\Awarning:/) { paint('warning:', :yellow) }
               else
                 eol = line.end_with?("\n") ? "\n" : ''
                 paint(line.chomp, :red) + eol
               end
        prefix + body
      end

      def paint(text, code)
        "\e[#{CODES.fetch(code)}m#{text}\e[0m"
      end
    end
  end
end
