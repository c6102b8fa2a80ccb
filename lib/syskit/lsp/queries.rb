# frozen_string_literal: true

module Syskit
  module LSP
    # The requests about a place in a document, answered by the capability
    # classes (Hover, Definition, Completion, DocumentSymbols) on the app
    # containing the document, loaded and with the editor's buffers, and
    # their answers in the protocol's shapes. Outside an app, or on a
    # document the editor has not opened, they answer nothing.
    #
    # Each capability is made once per check of the app (it builds the
    # site's catalog of the app once) and kept between requests.
    module Queries
      private

      def hover(params)
        markdown = at_position(params) do |app, path, text, line, character|
          capability(Hover, app).at(path, text, line, character)
        end
        { contents: { kind: 'markdown', value: markdown } } if markdown
      end

      def definition(params)
        locations = at_position(params) do |app, path, text, line, character|
          capability(Definition, app).at(path, text, line, character)
        end
        (locations || []).map { |location| protocol_location(location) }
      end

      def completion(params)
        items = at_position(params) do |app, path, text, line, character|
          capability(Completion, app).at(path, text, line, character)
        end
        { isIncomplete: false, items: (items || []).map { |item| completion_item(item) } }
      end

      def document_symbols(params)
        in_document(params) { |app, path, text| capability(DocumentSymbols, app).of(path, text) } || []
      end

      def at_position(params)
        line = params.dig(:position, :line)
        character = params.dig(:position, :character)
        in_document(params) { |app, path, text| yield app, path, text, line, character }
      end

      # Yields the app, the path and the text of the request's document.
      def in_document(params)
        path = URI.path(params.dig(:textDocument, :uri)) or return
        text = workspace.text(path) or return
        session = workspace.session_for(path) or return
        session.with_app do |app|
          @generation = session.generation
          yield app, path, text if app
        end
      end

      # The instance of capability +klass+ for +app+ as last checked.
      def capability(klass, app)
        cached_app, generation, instance = (@capabilities ||= {})[klass]
        return instance if cached_app.equal?(app) && generation == @generation

        klass.new(app).tap { |made| @capabilities[klass] = [app, @generation, made] }
      end

      def protocol_location(location)
        line = [location.lineno.to_i - 1, 0].max
        position = { line: line, character: 0 }
        { uri: uri_of(location.path), range: { start: position, end: position } }
      end

      # The capability's item, with its documentation as Markdown.
      def completion_item(item)
        result = item.compact
        documentation = result[:documentation]
        result[:documentation] = { kind: 'markdown', value: documentation } if documentation.is_a?(String)
        result
      end
    end
  end
end
