# frozen_string_literal: true

module Syskit
  module Robot
    # The comment block right above a statement, which Syskit makes the
    # documentation of a device (as MetaRuby reads documentation blocks):
    # the comment lines that directly precede the statement's line, without
    # their '#' and the indentation they share, joined by newlines; its
    # paragraphs that start with TODO are left out.
    #
    #   # The front-facing camera, 20 fps
    #   device(Devices::Camera::GigE, as: 'forward_camera')
    class DocComment
      COMMENT_MARK = /\A[ \t]*#/
      SPACE = ' '.ord
      TAB = "\t".ord
      HASH = '#'.ord
      BANG = '!'.ord

      def initialize
        # Each file is read once, however many statements it has; lines
        # are only cut out of it when they are comments (a robot of 10,000
        # devices would otherwise make a string per line of its file).
        @sources = {}
      end

      # The comment block above +location+, or nil.
      def above(location)
        return unless location

        content, starts = source_of(location.path)
        index = location.lineno - 2 # the line above, counted from 0
        block = nil
        while index >= 0 && (start = starts[index]) && comment_at?(content, start)
          line = content[start...(starts[index + 1] || content.size)].force_encoding(Encoding::UTF_8)
          (block ||= []).unshift(line.sub(COMMENT_MARK, '').rstrip)
          index -= 1
        end
        strip(block) if block
      end

      private

      # Whether the line starting at +start+ is a comment (not a #! line).
      # Looked at byte by byte: a regexp searched from an offset would scan
      # the rest of the file when it does not match there.
      def comment_at?(content, start)
        start += 1 while (byte = content.getbyte(start)) == SPACE || byte == TAB
        byte == HASH && content.getbyte(start + 1) != BANG
      end

      # The file's content and where each of its lines starts. Read as
      # bytes: offsets into a UTF-8 string are counted in characters, which
      # costs a scan of the string at each search.
      def source_of(path)
        @sources[path] ||= begin
          content = File.file?(path) ? File.binread(path) : ''.b
          starts = [0]
          at = -1
          while (at = content.index("\n", at + 1))
            starts << (at + 1)
          end
          [content, starts]
        end
      end

      # Removes the indentation the non-blank lines share.
      def strip(block)
        indent = block.reject(&:empty?).map { |line| line[/\A */].size }.min || 0
        text = block.map { |line| line[indent..] || '' }.join("\n")
        without_notes(text)
      end

      # A paragraph that starts with TODO is a note to the file's author
      # (the generators' placeholders), not documentation.
      def without_notes(text)
        return text unless text.match?(/^TODO\b/)

        kept = text.split(/\n{2,}/).reject { |paragraph| paragraph.start_with?('TODO') }.join("\n\n")
        kept.empty? ? nil : kept
      end
    end
  end
end
