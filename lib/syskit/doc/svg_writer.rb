# frozen_string_literal: true

require 'erb'

module Syskit
  module Doc
    # A small SVG writer for the site's charts: shapes and labels appended
    # to a string, coordinates written with at most one decimal whatever
    # their class (Rational, Float, Integer), so the same numbers give the
    # same bytes.
    class SvgWriter
      def initialize(width, height, label)
        @out = %(<svg class="chart" xmlns="http://www.w3.org/2000/svg" width="#{width}" height="#{height}" )
        @out << %(viewBox="0 0 #{width} #{height}" role="img" aria-label="#{h(label)}">\n<title>#{h(label)}</title>\n)
      end

      # A rectangle at +at+ ([x, y]) of +size+ ([width, height]).
      def rect(at, size, fill, css: nil)
        klass = css ? %( class="#{css}") : ''
        @out << %(<rect#{klass} x="#{num(at[0])}" y="#{num(at[1])}" width="#{num(size[0])}" ) <<
          %(height="#{num(size[1])}" fill="#{fill}"/>\n)
        self
      end

      # A label whose baseline starts (or, with +css+ 'end', ends) at +at+.
      def text(at, content, css)
        anchor = css.split.include?('end') ? ' text-anchor="end"' : ''
        @out << %(<text class="#{css}" x="#{num(at[0])}" y="#{num(at[1])}"#{anchor}>#{h(content)}</text>\n)
        self
      end

      # A dashed vertical line from +top+ to +bottom+ at +x+.
      def dashed(x, top, bottom, color) # rubocop:disable Naming/MethodParameterName -- a coordinate
        @out << %(<line x1="#{num(x)}" y1="#{top}" x2="#{num(x)}" y2="#{bottom}" stroke="#{color}" ) <<
          %(stroke-dasharray="3 2"/>\n)
        self
      end

      def to_s
        "#{@out}</svg>\n"
      end

      private

      def num(value)
        format('%.1f', value.to_f).delete_suffix('.0')
      end

      def h(text)
        ERB::Util.html_escape(text)
      end
    end
  end
end
