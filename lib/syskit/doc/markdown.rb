# frozen_string_literal: true

require 'erb'
require 'strscan'

module Syskit
  module Doc
    # The Markdown of syskit's guides as HTML, for the site: headings,
    # paragraphs, lists, fenced code blocks, tables, links, inline code,
    # bold and italic. That is what the guides use; anything else is shown
    # as the text it is, escaped. Headings get GitHub's anchors, so that a
    # link between guides works on GitHub and in the site alike. The HTML
    # is well-formed XML, as every page of the site is.
    class Markdown
      Heading = Struct.new(:level, :text, :id)

      FENCE = /\A```\s*([\w+-]*)\s*\z/
      HEADING = /\A(\#{1,6})\s+(.*?)\s*\z/
      ITEM = /\A {0,3}(?:([-*])|(\d{1,9})[.)])(?: +|\z)/
      TABLE_RULE = /\A\|?(?:\s*:?-{3,}:?\s*\|)+\s*:?-*:?\s*\z/

      # GitHub's anchor for a heading: its text without markup, lower case,
      # without punctuation, spaces made dashes.
      def self.slug(text)
        plain(text).downcase.gsub(/[^\p{L}\p{M}\p{N}\p{Pc} -]/, '').tr(' ', '-')
      end

      # +text+ without its inline markup.
      def self.plain(text)
        text.gsub(/\[((?:`[^`]*`|[^\]])*)\]\([^)\s]*\)/m, '\1').gsub(/\*\*|`/, '').gsub(/\s+/, ' ').strip
      end

      attr_reader :headings

      # +link+ is called with the target of each link and returns the
      # address to write, or nil to write the link's text alone (a file
      # the HTML cannot point at).
      def initialize(text, link: ->(target) { target })
        @lines = text.lines.map(&:chomp)
        @link = link
        @headings = []
        @paragraphs = []
        @html = parse.join("\n") << "\n"
      end

      def to_html
        @html
      end

      # The text of the first heading of level 1, without markup.
      def title
        heading = headings.find { |h| h.level == 1 }
        heading && Markdown.plain(heading.text)
      end

      # The first sentence of the first paragraph, without markup.
      def summary
        first = Markdown.plain(@paragraphs.first.to_s)
        first[/\A.*?[.!?](?=\s|\z)/] || first
      end

      private

      def h(text)
        ERB::Util.html_escape(text)
      end

      # The blocks' HTML, one string each.
      def parse
        blocks = []
        at = 0
        while at < @lines.size
          line = @lines[at]
          if line.strip.empty? then at += 1
          else
            at, html = block_at(at, line)
            blocks << html
          end
        end
        blocks
      end

      # [the index of the line after the block starting at +at+, its HTML]
      def block_at(at, line)
        if (m = FENCE.match(line)) then fence(at, m[1])
        elsif (m = HEADING.match(line)) then [at + 1, heading(m[1].size, m[2])]
        elsif table?(at) then table(at)
        elsif ITEM.match?(line) then list(at)
        else paragraph(at)
        end
      end

      def fence(at, language)
        stop = ((at + 1)...@lines.size).find { |i| @lines[i].start_with?('```') } || @lines.size
        code = @lines[(at + 1)...stop].join("\n")
        klass = language.empty? ? '' : %( class="language-#{h(language)}")
        [stop + 1, "<pre><code#{klass}>#{h(code)}</code></pre>"]
      end

      def heading(level, text)
        id = unique_id(Markdown.slug(text))
        @headings << Heading.new(level, text, id)
        %(<h#{level} id="#{h(id)}">#{inline(text)}</h#{level}>)
      end

      # GitHub's: the second heading of one text gets -1, the third -2.
      def unique_id(slug)
        @ids ||= Hash.new(0)
        count = @ids[slug]
        @ids[slug] += 1
        count.zero? ? slug : "#{slug}-#{count}"
      end

      def table?(at)
        @lines[at].start_with?('|') && TABLE_RULE.match?(@lines[at + 1].to_s)
      end

      def table(at)
        stop = ((at + 2)...@lines.size).find { |i| !@lines[i].start_with?('|') } || @lines.size
        head = cells(@lines[at]).map { |c| "<th>#{inline(c)}</th>" }.join
        rows = @lines[(at + 2)...stop].map { |l| "<tr>#{cells(l).map { |c| "<td>#{inline(c)}</td>" }.join}</tr>" }
        [stop, "<table>\n<thead><tr>#{head}</tr></thead>\n<tbody>\n#{rows.join("\n")}\n</tbody>\n</table>"]
      end

      # A row's cells; \| is a | inside a cell, code included (as GitHub
      # reads tables).
      def cells(line)
        line.strip.sub(/\A\|/, '').sub(/(?<!\\)\|\z/, '').split(/(?<!\\)\|/).map { |c| c.strip.gsub('\\|', '|') }
      end

      # A list: its items, each a marker line and the lines that continue
      # it (indented, or not: a lazy continuation); a blank line followed
      # by an item or an indented line goes on with the list.
      def list(at)
        ordered = ITEM.match(@lines[at])[2]
        items = []
        while at < @lines.size
          line = @lines[at]
          item = ITEM.match(line)
          if item && item[2].nil? == ordered.nil? then items << [line[item.end(0)..]]
          elsif line.strip.empty?
            break unless list_goes_on?(at)

            items.last << ''
          elsif line.start_with?(' ') || !starts_block?(line) then items.last << line
          else break
          end
          at += 1
        end
        [at, list_html(items, ordered)]
      end

      def list_goes_on?(at)
        following = @lines[(at + 1)..].find { |l| !l.strip.empty? }
        following && (ITEM.match?(following) || following.start_with?('  '))
      end

      def starts_block?(line)
        FENCE.match?(line) || HEADING.match?(line) || line.start_with?('|') || ITEM.match?(line)
      end

      def list_html(items, ordered)
        tag = ordered ? 'ol' : 'ul'
        start = ordered && ordered != '1' ? %( start="#{ordered.to_i}") : ''
        lis = items.map do |lines|
          paragraphs = lines.map(&:strip).join("\n").strip.split(/\n{2,}/)
          body = paragraphs.size == 1 ? inline(paragraphs.first) : paragraphs.map { |p| "<p>#{inline(p)}</p>" }.join
          "<li>#{body}</li>"
        end
        "<#{tag}#{start}>\n#{lis.join("\n")}\n</#{tag}>"
      end

      def paragraph(at)
        stop = ((at + 1)...@lines.size).find do |i|
          line = @lines[i]
          line.strip.empty? || FENCE.match?(line) || HEADING.match?(line) || line.match?(/\A[-*] /) || table?(i)
        end || @lines.size
        text = @lines[at...stop].map(&:strip).join("\n")
        @paragraphs << text
        [stop, "<p>#{inline(text)}</p>"]
      end

      # Inline markup, left to right: code spans first (nothing inside
      # them is markup), links, bold, italic, backslash escapes.
      def inline(text)
        s = StringScanner.new(text)
        out = +''
        until s.eos?
          out << if (plain = s.scan(/[^`\[*\\]+/)) then h(plain)
                 elsif s.scan(/(`+)(.+?)(?<!`)\1(?!`)/m) then "<code>#{h(s[2].tr("\n", ' ').strip)}</code>"
                 elsif s.scan(/\[((?:`[^`]*`|[^\]`])+)\]\(([^)\s]+)\)/m) then link(s[1], s[2])
                 elsif s.scan(/\*\*(?=\S)(.+?)(?<=\S)\*\*/m) then "<strong>#{inline(s[1])}</strong>"
                 elsif s.scan(/\*(?=[^\s*])(.+?)(?<=[^\s*])\*/m) then "<em>#{inline(s[1])}</em>"
                 elsif s.scan(/\\([!-\/:-@\[-`{-~])/) then h(s[1])
                 else h(s.getch)
                 end
        end
        out
      end

      def link(text, target)
        href = @link.call(target)
        href ? %(<a href="#{h(href)}">#{inline(text)}</a>) : inline(text)
      end
    end
  end
end
