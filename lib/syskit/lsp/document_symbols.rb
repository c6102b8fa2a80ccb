# frozen_string_literal: true

require 'syskit/doc/catalog'
require 'syskit/lsp/nesting'

module Syskit
  module LSP
    # The outline of a file: the models, profiles, devices and definitions
    # the loaded app recorded as declared in it (the site's catalog, with
    # each model's declaration location), as the protocol's DocumentSymbol
    # Hashes. A composition's children and a profile's devices and
    # definitions are its children; a model declared by a class spans its
    # body (Nesting gives its last line), the rest their statement's line.
    #
    # A file the app could not load declared nothing: its outline is empty.
    class DocumentSymbols
      # The protocol's SymbolKind values used here.
      KINDS = { module: 2, class: 5, field: 8, interface: 11, function: 12, variable: 13 }.freeze
      MODEL_KINDS = { device: :class, bus: :class, service: :interface, composition: :class,
                      task_model: :class, profile: :module }.freeze

      attr_reader :app

      def initialize(app)
        @app = app
      end

      def catalog
        @catalog ||= Doc::Catalog.new(app)
      end

      # The symbols of +path+, whose buffer is +text+, in line order.
      def of(path, text)
        @text = text.to_s.scrub
        @lines = @text.lines.map(&:chomp)
        @scopes = nil
        path = File.expand_path(path)
        MODEL_KINDS.flat_map { |key, kind| symbols_of(key, kind, path) }
                   .sort_by { |s| s[:range][:start][:line] }
      end

      private

      def symbols_of(key, kind, path)
        catalog.entries(key).select { |e| e.declared_at&.path == path }.filter_map do |entry|
          children = send(:"children_of_#{key}", entry.object, path) if respond_to?(:"children_of_#{key}", true)
          symbol(entry.name, kind, entry.declared_at.lineno, detail: entry.kind.singular, children: children || [])
        end
      end

      def children_of_composition(model, path)
        model.each_child.filter_map do |name, child|
          symbol(name, :field, line_in(child, path), detail: 'child')
        end
      end

      def children_of_profile(profile, path)
        devices = profile.robot.each_master_device.filter_map do |device|
          symbol(device.name, :variable, line_in(device, path), detail: device.com_bus? ? 'bus' : 'device')
        end
        definitions = profile.definitions.values.filter_map do |definition|
          symbol("#{definition.name}_def", :function, line_in(definition, path), detail: 'definition')
        end
        (devices + definitions).sort_by { |s| s[:range][:start][:line] }
      end

      # The line of +object+'s declaration when it is in +path+.
      def line_in(object, path)
        object.declared_at.lineno if object.declared_at&.path == path
      end

      # A DocumentSymbol at 1-based +lineno+ of the buffer; nil when the
      # buffer has no such line (it changed since the app was loaded).
      def symbol(name, kind, lineno, detail:, children: [])
        return unless lineno.to_i.between?(1, @lines.size)

        line = lineno - 1
        text = @lines[line]
        start = text[/\A\s*/].size
        selection = range(line, utf16(text[0, start]), line, utf16(text))
        last = body_end(lineno)
        whole = last ? range(line, 0, last - 1, utf16(@lines[last - 1].to_s)) : selection
        whole = enclose(whole, children.map { |c| c[:range][:end] })
        { name: name, detail: detail, kind: KINDS.fetch(kind), range: whole, selectionRange: selection,
          children: children }
      end

      # The last line of the class or module whose header is at +lineno+.
      def body_end(lineno)
        @scopes ||= scopes
        @scopes.find { |s| s.first_line == lineno }&.last_line
      end

      def scopes
        parser = Nesting.parse(@text)
        parser.error? ? [] : parser.scopes
      end

      # +range+ grown to end at the last of +ends+ (its children's).
      def enclose(range, ends)
        key = ->(pos) { [pos[:line], pos[:character]] }
        last = ends.max_by(&key)
        last && (key.call(last) <=> key.call(range[:end])) == 1 ? range.merge(end: last) : range
      end

      def range(line, char, end_line, end_char)
        { start: { line: line, character: char }, end: { line: end_line, character: end_char } }
      end

      def utf16(text)
        text.encode('UTF-16LE').bytesize / 2
      end
    end
  end
end
