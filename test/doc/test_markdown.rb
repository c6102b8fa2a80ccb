# frozen_string_literal: true

require 'helper'
require 'rexml/document'
require 'syskit/doc/markdown'

module Syskit
  # The Markdown of the guides as the site's HTML (Doc::Markdown): what
  # the guides use, rendered as GitHub renders it.
  class TestMarkdown < Minitest::Test
    def html(text, **options)
      Doc::Markdown.new(text, **options).to_html
    end

    def test_headings_get_githubs_anchors
      out = html("# syskit — the `doc` site\n\n## Reviewing a change: plan diffs\n\n## Names\n\n### Names\n")
      assert_equal <<~HTML, out
        <h1 id="syskit--the-doc-site">syskit — the <code>doc</code> site</h1>
        <h2 id="reviewing-a-change-plan-diffs">Reviewing a change: plan diffs</h2>
        <h2 id="names">Names</h2>
        <h3 id="names-1">Names</h3>
      HTML
      assert_equal 'in-syskit-check-and-syskit-plan', Doc::Markdown.slug('In `syskit check` (and `syskit plan`)')
      assert_equal 'formats-and-the-example-apps-plan', Doc::Markdown.slug("Formats, and the example app's plan")
    end

    def test_paragraphs_and_inline_markup
      out = html("A **bold** and *italic* `a < b` with\n[a link](other.md#x) and \\*stars\\*.\n\n" \
                 "Another `one\nspan`.\n")
      assert_equal <<~HTML, out
        <p>A <strong>bold</strong> and <em>italic</em> <code>a &lt; b</code> with
        <a href="other.md#x">a link</a> and *stars*.</p>
        <p>Another <code>one span</code>.</p>
      HTML
    end

    def test_links_the_caller_cannot_point_at_are_their_text
      only_plan = ->(target) { 'plan.html' if target == 'plan.md' }
      out = html('[the `README`](../../README.md) and [plan](plan.md)', link: only_plan)
      assert_equal %(<p>the <code>README</code> and <a href="plan.html">plan</a></p>\n), out
    end

    def test_lists_with_continuations_and_loose_items
      out = html("- one\n  continued `x\n  y`\n- two\n\n- three\n\n1. first\n2. second\n\n3. third\n")
      assert_equal <<~HTML, out
        <ul>
        <li>one
        continued <code>x y</code></li>
        <li>two</li>
        <li>three</li>
        </ul>
        <ol>
        <li>first</li>
        <li>second</li>
        <li>third</li>
        </ol>
      HTML
      assert_includes html("3. three\n4. four\n"), '<ol start="3">'
    end

    def test_code_blocks_are_escaped_as_written
      out = html("```ruby\n# models/x.rb\nputs '<b>' if a && b\n\n  end\n```\nafter\n")
      assert_equal <<~HTML, out
        <pre><code class="language-ruby"># models/x.rb
        puts &#39;&lt;b&gt;&#39; if a &amp;&amp; b

          end</code></pre>
        <p>after</p>
      HTML
    end

    def test_tables_with_escaped_bars
      out = html("| command | what |\n| --- | --- |\n| `plan --format text\\|json` | *the* plan |\n")
      assert_equal <<~HTML, out
        <table>
        <thead><tr><th>command</th><th>what</th></tr></thead>
        <tbody>
        <tr><td><code>plan --format text|json</code></td><td><em>the</em> plan</td></tr>
        </tbody>
        </table>
      HTML
    end

    def test_title_and_summary_are_plain_text
      doc = Doc::Markdown.new("# The `syskit doc` site\n\n`syskit doc` writes [a site](x.md). It is static.\n")
      assert_equal 'The syskit doc site', doc.title
      assert_equal 'syskit doc writes a site.', doc.summary
    end

    # Every guide is well-formed XML once rendered, as the site's pages
    # must be.
    def test_every_guide_renders_to_well_formed_xml
      guides = Dir.glob(File.join(GEM_ROOT, 'doc', 'guides', '*.md'))
      refute_empty guides
      guides.each do |file|
        document = REXML::Document.new("<div>#{html(File.read(file))}</div>")
        assert document.root.has_elements?, "#{file} renders to nothing"
      rescue REXML::ParseException => e
        flunk "#{file}: #{e.message.lines.first}"
      end
    end
  end
end
