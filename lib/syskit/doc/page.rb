# frozen_string_literal: true

require 'erb'
require 'syskit/render/text'

module Syskit
  module Doc
    # What a template sees: the page being written (its path in the site,
    # so that links are relative and the site works from file://) and
    # helpers that write HTML. Every value a template inserts goes through
    # #h or a helper that escapes it.
    class Page
      attr_reader :site, :path, :catalog

      def initialize(site, path)
        @site = site
        @catalog = site.catalog
        @path = path
      end

      # The template +name+ (templates/doc/NAME.html.erb) with +locals+.
      def render(name, **locals)
        scope = binding
        locals.each { |key, value| scope.local_variable_set(key, value) }
        site.template(name).result(scope)
      end

      def h(text)
        ERB::Util.html_escape(text.to_s)
      end

      # +target+ (a path from the site's root) relative to this page.
      def url(target)
        ('../' * path.count('/')) + target
      end

      # A link to the page of +object+ (a model, library, profile or
      # entry), or its name when the site has no page for it.
      def link(object, text = nil)
        entry = object.is_a?(Entry) ? object : catalog.entry_for(object)
        text ||= entry ? entry.name : object.to_s
        return %(<span class="name">#{name(text)}</span>) unless entry

        %(<a href="#{h(url(entry.path))}">#{name(text)}</a>)
      end

      # A model name that may break after each :: in a narrow column.
      def name(text)
        h(text).gsub('::', '::<wbr />')
      end

      # The documentation text as paragraphs (blank lines separate them;
      # indented lines are kept as written, as code).
      def doc_html(text)
        return '' if text.to_s.strip.empty?

        text.strip.split(/\n[ \t]*\n/).map do |para|
          if para.lines.all? { |l| l.start_with?('  ') }
            "<pre>#{h(para)}</pre>"
          else
            "<p>#{h(para.gsub(/\s*\n\s*/, ' '))}</p>"
          end
        end.join("\n")
      end

      # A value as the plan's text shows it: plain data written as JSON,
      # CAN ids and masks in hex (by their property's name).
      def value(data, name: nil)
        h(Render::Text.plain(data, +'', ids: Render::Output.id_name?(name.to_s)))
      end

      # A port's type as its declaration names it, and, for a typedef, the
      # type it stands for beside it.
      def port_type(port)
        declared = port.declared_type if port.respond_to?(:declared_type)
        return %(<code>#{h(port.type.name)}</code>) unless declared

        %(<code>#{h(declared)}</code> <span class="muted">= <code>#{h(port.type.name)}</code></span>)
      end

      # Where something was declared: its path relative to its bundle, and
      # line.
      def location(loc)
        return '' unless loc

        root = site.app.bundles.find { |b| b.owns?(loc.path) }&.root
        %(<code class="location">#{h(loc.to_s(root))}</code>)
      end

      # The badge saying where an entry comes from, when it is not the app.
      def origin(entry)
        return '' unless entry&.origin

        %( <span class="badge origin" title="from the bundle #{h(entry.origin)}">#{h(entry.origin)}</span>)
      end

      # "1 frame", "2 frames"
      def count(number, word)
        Naming.count(number, word)
      end
    end
  end
end
