# frozen_string_literal: true

require 'helper'

module Syskit
  module SelfTest
    # The user documentation (README.md and the guides under doc/) as its
    # tests read it: "the output shown under `$ syskit plan` in the plan
    # guide" is
    #
    #   Docs.guide('plan').output_of('bundle exec bin/syskit plan --app examples/awesome_robot')
    #
    # so that a test says which snippet it checks, wherever it lives.
    module Docs
      # README.md, then every Markdown file under doc/ (paths relative to
      # the gem's root).
      def self.paths
        ['README.md'] + Dir.glob('doc/**/*.md', base: GEM_ROOT).sort
      end

      def self.read(path)
        (@read ||= {})[path] ||= Text.new(path, File.read(File.join(GEM_ROOT, path)))
      end

      def self.readme
        read('README.md')
      end

      # doc/guides/NAME.md
      def self.guide(name)
        read("doc/guides/#{name}.md")
      end

      def self.all
        paths.map { |path| read(path) }
      end

      # Assertions on what documents show.
      module Assertions
        # +shown+ is an excerpt of +out+: each run of lines between "..."
        # lines is in +out+ whole, as shown, and the runs are in order.
        def assert_shown_excerpt(shown, out, what)
          runs = shown.split(/^ *\.\.\.\n/)
          at = 0
          runs.each do |run|
            found = out.index(run, at)
            assert found, "#{what} shows lines the command does not print (after offset #{at}):\n#{run}"
            assert found.zero? || out[found - 1] == "\n", "#{what} cuts a line:\n#{run}"
            at = found + run.size
          end
          runs.size
        end
      end

      # A document, or a section of one: its text, and the parts of it
      # tests check. Lines inside fenced code blocks are never headings.
      class Text
        attr_reader :path, :text

        def initialize(path, text)
          @path = path
          @text = text
        end

        def to_s
          text
        end

        # The headings outside code blocks: [level, title, line index].
        def headings
          @headings ||= begin
            in_code = false
            text.lines.each_with_index.filter_map do |line, i|
              in_code = !in_code if line.start_with?('```')
              next if in_code

              [Regexp.last_match(1).size, Regexp.last_match(2).strip, i] if line =~ /\A(\#{1,6}) (.*)$/
            end
          end
        end

        # The section under the heading +title+ (its text, or a Regexp
        # matching it), up to the next heading of the same or a higher
        # level.
        def section(title)
          lines = text.lines
          level, _, start = headings.find { |_, t, _| title.is_a?(Regexp) ? t.match?(title) : t == title }
          raise ArgumentError, "#{path} has no heading #{title.inspect}" unless start

          stop = headings.find { |l, _, i| i > start && l <= level }&.last || lines.size
          Text.new("#{path} (#{title})", lines[start...stop].join)
        end

        # The fenced code blocks, as [language, body] ('' without one).
        def code_blocks(language = nil)
          blocks = text.scan(/^```([\w-]*)\n(.*?)^```/m)
          language ? blocks.select { |lang, _| lang == language }.map(&:last) : blocks
        end

        # The code block of +language+, the only one or the first.
        def code_block(language)
          code_blocks(language).first || raise(ArgumentError, "#{path} has no #{language} block")
        end

        # The output shown under "$ COMMAND" in a code block: the lines
        # that follow it, up to the next "$ " line or the end of the block.
        def output_of(command)
          text[/^\$ #{Regexp.escape(command)}\n((?:(?!\$ |```).*\n)*)/, 1] ||
            raise(ArgumentError, "#{path} shows no output of #{command}")
        end

        # Every "$ PREFIX..." command shown, with its output:
        # [[the command after PREFIX, output]].
        def commands(prefix)
          text.scan(/^\$ #{Regexp.escape(prefix)}(.*)\n((?:(?!\$ |```).*\n)*)/)
        end

        # Snippets headed by a file of the example app ("# models/x.rb",
        # optionally followed by a remark in parentheses):
        # [[path, body]].
        def file_snippets
          text.scan(/^```(?:ruby|yaml)\n# (\S+\.(?:rb|yml|orogen))(?: \([^)\n]*\))?\n(.*?)^```/m)
        end

        # Markdown links outside code: [[target, line number]].
        def links
          in_code = false
          text.lines.each_with_index.flat_map do |line, i|
            in_code = !in_code if line.start_with?('```')
            next [] if in_code

            line.gsub(/`[^`]*`/, '').scan(/\]\(([^)\s]+)\)/).map { |(target)| [target, i + 1] }
          end
        end
      end
    end
  end
end
