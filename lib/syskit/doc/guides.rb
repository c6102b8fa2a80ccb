# frozen_string_literal: true

require 'syskit/doc/markdown'

module Syskit
  module Doc
    # syskit's guides (doc/guides/*.md in the gem), as the site shows them:
    # a page each, guides/NAME.html, listed on the index in the order of
    # the README's "Where to read on", each with its line there (a guide
    # the README does not list comes last, with its first sentence).
    # Links between guides lead to their pages; a link to another file of
    # the gem (the README, its code), which the site does not have, is
    # written as its text.
    class Guides
      GEM_ROOT = File.expand_path('../../..', __dir__)

      Guide = Struct.new(:name, :title, :summary, :html) do
        # Its page, relative to the site's root.
        def path
          "guides/#{name}.html"
        end
      end

      def initialize(root = GEM_ROOT)
        @dir = File.join(root, 'doc', 'guides')
        @readme = File.join(root, 'README.md')
      end

      def to_a
        @to_a ||= begin
          listed = read_on
          names = Dir.glob('*.md', base: @dir).map { |file| File.basename(file, '.md') }
          ((listed.keys & names) + (names - listed.keys).sort).map { |name| guide(name, listed[name]) }.freeze
        end
      end

      def each(&)
        to_a.each(&)
      end

      def size
        to_a.size
      end

      # Where a guide's link to +target+ leads in the site, or nil.
      def href(target)
        return target if target.start_with?('#') || target.match?(/\A[a-z][a-z+.-]*:/i)

        path, anchor = target.split('#', 2)
        file = File.expand_path(path, @dir)
        return unless File.dirname(file) == @dir && file.end_with?('.md') && File.file?(file)

        "#{File.basename(file, '.md')}.html#{"##{anchor}" if anchor}"
      end

      private

      def guide(name, line)
        markdown = Markdown.new(File.read(File.join(@dir, "#{name}.md"), encoding: 'UTF-8'), link: method(:href))
        Guide.new(name, markdown.title || name, line || markdown.summary, markdown.to_html).freeze
      end

      # The guides the README lists under "Where to read on", in order:
      # name => the line after the link ("- [Title](doc/guides/NAME.md):
      # line", up to the next item or blank line), without markup.
      def read_on
        return {} unless File.file?(@readme)

        section = File.read(@readme, encoding: 'UTF-8')[/^## Where to read on\n(.*?)(?=^## |\z)/m, 1].to_s
        section.split(/^(?=- \[)/).filter_map do |item|
          found = item.match(%r{\A- \[[^\]]*\]\(doc/guides/([\w-]+)\.md\):?\s*(.*)}m)
          [found[1], Markdown.plain(found[2].split(/\n\s*\n/).first.to_s)] if found
        end.to_h
      end
    end
  end
end
