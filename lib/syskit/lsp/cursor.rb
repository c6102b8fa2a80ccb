# frozen_string_literal: true

require 'ripper'
require 'syskit/lsp/quietly'

module Syskit
  module LSP
    # What is at a position of a buffer, read off its line's tokens (Ripper's
    # lexer, which also lexes a line being typed): the token under the
    # cursor, the constant path or OroGen.lib.Task chain it ends, the string
    # it is in and the call that string is an argument of.
    #
    # +line+ and +character+ are the protocol's: 0-based, the character in
    # UTF-16 code units; Ripper counts bytes.
    class Cursor
      Token = Struct.new(:col, :type, :text) do
        def end_col
          col + text.bytesize
        end
      end

      # A string literal under the cursor: its text, the call it is an
      # argument of (nil when none on this line) and the keyword it follows
      # (+as+ in `as: 'gps'`).
      Str = Struct.new(:text, :call, :label)

      attr_reader :path, :text, :lineno, :col, :line_text, :tokens

      # A +text+ that is not valid UTF-8 (a file read from disk, in
      # Latin-1) is read with its invalid bytes replaced.
      def initialize(path, text, line, character)
        @path = path
        @text = text.to_s.scrub
        @lineno = line + 1
        @line_text = @text.lines[line].to_s.chomp
        @col = Cursor.byte_offset(@line_text, character)
        @tokens = LSP.quietly { Ripper.lex(@line_text) }.map { |(_, c), type, tok| Token.new(c, type, tok) }
      end

      # The byte offset of the UTF-16 position +character+ in +line+.
      def self.byte_offset(line, character)
        units = 0
        line.each_char.with_index do |char, index|
          return line[0, index].bytesize if units >= character

          units += char.ord > 0xFFFF ? 2 : 1
        end
        line.bytesize
      end

      # The index of the token the cursor is in (or just after the end of).
      def index
        return @index if defined?(@index)

        @index = @tokens.index { |t| t.col <= col && col < t.end_col && t.type != :on_sp } ||
                 @tokens.rindex { |t| t.end_col == col && t.type != :on_sp }
      end

      def token
        index && @tokens[index]
      end

      # The constant path ending at the token under the cursor
      # ('Devices::GPS' on GPS of Devices::GPS::Ublox), nil when the
      # cursor is not on a constant. A leading :: is kept.
      def constant_path
        path_ending_at(index) if token&.type == :on_const && !orogen_chain
      end

      # The constant path of the receiver of the method under the cursor
      # (+Base+ of Base.gps_dev), nil when it is not a constant.
      def receiver_constant
        i = index
        path_ending_at(i - 2) if i && i >= 2 && @tokens[i - 1].type == :on_period && @tokens[i - 2].type == :on_const
      end

      # ['lib'] or ['lib', 'Task'] when the cursor is on the library or the
      # task of an OroGen.lib.Task chain.
      def orogen_chain
        return unless token && %i[on_ident on_const].include?(token.type)

        chain = [token.text]
        i = index
        while i >= 2 && @tokens[i - 1].type == :on_period
          chain.unshift(@tokens[i - 2].text)
          i -= 2
        end
        chain.drop(1) if chain.first == 'OroGen' && chain.size.between?(2, 3)
      end

      # The identifier under the cursor (gps_dev, pose_port...).
      def identifier
        token.text if token&.type == :on_ident
      end

      # The receiver of the method under the cursor, when it is an
      # identifier (+follower_child+ of follower_child.pose_port).
      def receiver
        i = index
        @tokens[i - 2].text if i && i >= 2 && @tokens[i - 1].type == :on_period && @tokens[i - 2].type == :on_ident
      end

      # The string literal the cursor is in, nil when it is not in one.
      def string
        i = string_index
        return unless i

        tok = @tokens[i]
        content = tok.type == :on_tstring_content ? tok.text : ''
        beg = tok.type == :on_tstring_content ? i - 1 : i
        Str.new(content, call_of(beg), label_before(beg))
      end

      # The text of the line before the cursor.
      def before
        @line_text.byteslice(0, col).to_s
      end

      private

      # The index of the content of the string the cursor is in, or of
      # its opening quote when it is empty and the line ends there.
      def string_index
        i = index
        return unless i

        i -= 1 if %i[on_tstring_beg on_tstring_end].include?(@tokens[i].type) && @tokens[i].end_col == col
        i += 1 if @tokens[i].type == :on_tstring_beg && @tokens[i + 1]&.type == :on_tstring_content
        i if @tokens[i] && (@tokens[i].type == :on_tstring_content || string_start?(i))
      end

      # The constant path whose last name is the token at +index+.
      def path_ending_at(index)
        parts = [@tokens[index].text]
        i = index
        while @tokens[i - 1]&.text == '::' && i >= 2 && @tokens[i - 2].type == :on_const
          parts.unshift(@tokens[i - 2].text)
          i -= 2
        end
        parts.unshift('') if top_level?(i)
        parts.join('::')
      end

      # Whether the constant path starting at token +index+ is ::Name.
      def top_level?(index)
        index >= 1 && @tokens[index - 1].text == '::' && (index < 2 || @tokens[index - 2].type == :on_sp)
      end

      def string_start?(index)
        @tokens[index].type == :on_tstring_beg && @tokens[index + 1].nil?
      end

      def label_before(index)
        prev = previous_significant(index)
        @tokens[prev].text.delete_suffix(':') if prev && @tokens[prev].type == :on_label
      end

      # The method whose argument list holds the token at +index+: the
      # closest identifier before it that is not inside a pair of
      # parentheses closed before +index+.
      def call_of(index)
        depth = 0
        (index - 1).downto(0) do |i|
          tok = @tokens[i]
          case tok.type
          when :on_rparen, :on_rbracket then depth += 1
          when :on_lparen, :on_lbracket then depth -= 1 if depth.positive?
          when :on_ident then return tok.text if depth.zero?
          end
        end
        nil
      end

      def previous_significant(index)
        (index - 1).downto(0).find { |i| @tokens[i].type != :on_sp }
      end
    end
  end
end
