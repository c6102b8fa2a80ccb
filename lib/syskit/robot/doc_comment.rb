# frozen_string_literal: true

module Syskit
  module Robot
    # The comment block right above a statement, which Syskit makes the
    # documentation of a device (as MetaRuby reads documentation blocks):
    # the comment lines that directly precede the statement's line, without
    # their '#' and the indentation they share, joined by newlines.
    #
    #   # The front-facing camera, 20 fps
    #   device(Devices::Camera::GigE, as: 'forward_camera')
    class DocComment
      COMMENT = /\A\s*#(?!!)(.*)\z/m

      def initialize
        # Each file is read once, however many statements it has.
        @lines = {}
      end

      # The comment block above +location+, or nil.
      def above(location)
        return unless location

        lines = lines_of(location.path)
        block = []
        index = location.lineno - 2
        while index >= 0 && (line = lines[index]) && (match = COMMENT.match(line))
          block.unshift(match[1].rstrip)
          index -= 1
        end
        strip(block) unless block.empty?
      end

      private

      def lines_of(path)
        @lines[path] ||= File.file?(path) ? File.readlines(path) : []
      end

      # Removes the indentation the non-blank lines share.
      def strip(block)
        indent = block.reject(&:empty?).map { |line| line[/\A */].size }.min || 0
        block.map { |line| line[indent..] || '' }.join("\n")
      end
    end
  end
end
