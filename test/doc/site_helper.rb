# frozen_string_literal: true

require 'docs_helper'
require 'rexml/document'

module Syskit
  module SelfTest
    # The example app's site, written once per test run through the
    # command users type, and ways to read its pages.
    module SiteHelper
      EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')
      # syskit's guides, each a page of every site.
      GUIDES = Dir.glob('*.md', base: File.join(GEM_ROOT, 'doc', 'guides')).map { |f| File.basename(f, '.md') }.sort

      # [directory, what syskit doc printed] of the example app's site.
      def self.example_site
        @example_site ||= begin
          dir = File.join(Dir.mktmpdir('syskit-doc'), 'site')
          Minitest.after_run { FileUtils.rm_rf(File.dirname(dir)) }
          [dir, yield(dir)]
        end
      end

      def example_site
        SiteHelper.example_site do |dir|
          out, err, status = run_cli('doc', '--app', EXAMPLE, '--output', dir)
          raise "syskit doc failed (#{status}): #{err}" unless status.zero?

          out
        end.first
      end

      # The site's files, relative to +dir+, sorted.
      def site_files(dir)
        Dir.glob('**/*', base: dir).select { |f| File.file?(File.join(dir, f)) }.sort
      end

      def html_pages(dir)
        site_files(dir).grep(/\.html\z/)
      end

      # The page at +path+ of the site in +dir+, parsed as XML: the pages
      # are written so that they are well-formed XML too (polyglot HTML),
      # which lets REXML check them and tests query them.
      def page(path, dir = example_site)
        REXML::Document.new(File.read(File.join(dir, path)))
      end

      # The text of the elements +xpath+ finds, whitespace squeezed.
      def texts(doc, xpath)
        REXML::XPath.match(doc, xpath).map { |e| squeeze(e) }
      end

      # Cells of a row and terms of a list are separated by a space.
      def squeeze(element)
        text_of(element).gsub(/\s+/, ' ').strip
      end

      def text_of(node)
        return node.value if node.is_a?(REXML::Text)
        return '' unless node.is_a?(REXML::Element)

        node.children.map { |child| text_of(child) }.join(%w[tr dl].include?(node.name) ? ' ' : '')
      end
    end
  end
end
