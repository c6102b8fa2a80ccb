# frozen_string_literal: true

require 'ripper'
require 'syskit/lsp/quietly'

module Syskit
  module LSP
    # The modules and classes whose body holds a line of a Ruby file, by
    # Ripper's parser events: each module or class is reported when its
    # +end+ is read, which gives its last line; its name gives the first.
    # This is how a constant written in a file is looked up, as Ruby does:
    # from the innermost scope out.
    class Nesting < Ripper
      Scope = Struct.new(:name, :first_line, :last_line)

      # The full names of the scopes around +lineno+ (1-based), innermost
      # first; empty when the text does not parse.
      def self.at(text, lineno)
        parser = parse(text)
        return [] if parser.error?

        enclosing = parser.scopes.select { |s| lineno.between?(s.first_line, s.last_line) }.sort_by(&:first_line)
        names = []
        enclosing.each do |s|
          names << (s.name.start_with?('::') ? s.name[2..] : [names.last, s.name].compact.join('::'))
        end
        names.reverse
      end

      # The parser, once it has read +text+ (without printing warnings).
      def self.parse(text)
        parser = new(text.to_s)
        LSP.quietly { parser.parse }
        parser
      end

      attr_reader :scopes

      def initialize(*)
        super
        @scopes = []
      end

      private

      def on_const(tok)
        [tok, lineno]
      end

      def on_const_ref(const)
        const
      end

      def on_var_ref(ref)
        ref
      end

      def on_top_const_ref(const)
        ["::#{const[0]}", const[1]] if const.is_a?(Array)
      end

      def on_const_path_ref(parent, const)
        return unless parent.is_a?(Array) && const.is_a?(Array)

        ["#{parent[0]}::#{const[0]}", parent[1]]
      end

      def on_module(ref, _body)
        record(ref)
      end

      def on_class(ref, _superclass, _body)
        record(ref)
      end

      def record(ref)
        @scopes << Scope.new(ref[0], ref[1], lineno) if ref.is_a?(Array) && ref[0].is_a?(String)
        nil
      end
    end
  end
end
