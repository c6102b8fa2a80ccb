# frozen_string_literal: true

require 'docs_helper'
require 'psych'
require 'syskit/doc/markdown'

module Syskit
  # What every document (README.md, doc/**/*.md) shows of the example apps
  # is in them, and its links lead somewhere.
  class TestDocs < Minitest::Test
    EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')
    CORPUS = File.join(GEM_ROOT, 'test', 'fixtures', 'broken')

    # Snippets headed by a file of the example app are excerpts of that
    # file: each line, in order (comments after code aside). A path
    # starting with examples/NAME/ is a file of another example app.
    def test_snippets_headed_by_a_file_are_excerpts_of_the_example_apps
      snippets = SelfTest::Docs.all.flat_map { |doc| doc.file_snippets.map { |path, body| [doc, path, body] } }
      assert_operator snippets.size, :>=, 14
      assert_operator snippets.count { |_, path, _| path.start_with?('examples/arm_lab/') }, :>=, 6
      snippets.each do |doc, path, body|
        file = path.start_with?('examples/') ? File.join(GEM_ROOT, path) : File.join(EXAMPLE, path)
        assert File.file?(file), "#{doc.path}'s snippet of #{path}: the example app has no such file"
        assert_excerpt File.readlines(file), body, "#{doc.path}'s snippet of #{path}"
      end
    end

    # Relative links lead to a file of the gem and, given an anchor, to a
    # heading of that Markdown file (GitHub's anchors, Doc::Markdown's).
    def test_every_relative_link_leads_to_a_file_and_its_anchor
      checked = 0
      SelfTest::Docs.all.each do |doc|
        doc.links.each do |target, line|
          next if target.match?(/\A[a-z][a-z+.-]*:/i) # https:, mailto:

          assert_link_resolves(doc, target, "#{doc.path}:#{line}: #{target}")
          checked += 1
        end
      end
      assert_operator checked, :>=, 40
    end

    def test_the_error_corpus_count_is_the_number_of_cases
      said = SelfTest::Docs.guide('troubleshooting')
                           .text[%r{under `test/fixtures/broken/` \(one broken app per case, (\d+)\s}, 1]
      refute_nil said, "the troubleshooting guide no longer gives the corpus's size"
      cases = Dir.children(File.join(GEM_ROOT, 'test', 'fixtures', 'broken'))
                 .count { |c| File.directory?(File.join(GEM_ROOT, 'test', 'fixtures', 'broken', c)) }
      assert_equal cases, Integer(said)
    end

    def test_the_compositions_guide_shows_a_definition_s_plan
      command = 'bundle exec bin/syskit plan --app examples/arm_lab Bench reach_target_def'
      shown = SelfTest::Docs.guide('compositions').output_of(command)
      out, err, status = run_cli(*command.split.drop(3))
      assert_equal 0, status, err
      assert_equal out, shown
    end

    # Bench's definitions are alternatives: its plan is the devices'.
    def test_the_compositions_guide_shows_why_the_whole_profile_is_the_devices_plan
      command = 'bundle exec bin/syskit plan --app examples/arm_lab Bench 2>&1 >/dev/null'
      shown = SelfTest::Docs.guide('compositions').output_of(command)
      out, err, status = run_cli('plan', '--app', 'examples/arm_lab', 'Bench')
      assert_equal 0, status, err
      assert_match(/^Tasks \(3\)$/, out)
      refute_match(/^Compositions/, out)
      assert_equal shown, err
    end

    # The errors the compositions guide shows are printed, as shown, by
    # the cases of the error corpus located at their first line.
    def test_the_compositions_guide_shows_errors_as_printed
      blocks = SelfTest::Docs.guide('compositions').section('Errors').code_blocks('')
      assert_operator blocks.size, :>=, 8
      blocks.each do |shown|
        printed = corpus_cases_at(shown.lines.first).map do |kase|
          out, err, = run_cli(kase['command'], *Array(kase['args']).map(&:to_s), '--app', kase['dir'])
          (kase['command'] == 'check' ? out : err).lines.first(2).join
        end
        assert_includes printed, shown, 'no case of the error corpus prints it'
      end
    end

    def test_the_plan_guide_shows_the_whole_plan
      shown = SelfTest::Docs.guide('plan').output_of('bundle exec bin/syskit plan --app examples/awesome_robot')
      out, err, status = run_cli('plan', '--app', 'examples/awesome_robot')
      assert_equal 0, status, err
      assert_equal out, shown
    end

    private

    # The cases of the error corpus whose expected location and message
    # are those of +line+ ("file:line: message").
    def corpus_cases_at(line)
      location, message = line.chomp.split(': ', 2)
      found = Dir[File.join(CORPUS, '*', 'expected.yml')].filter_map do |path|
        kase = { 'command' => 'check' }.merge(Psych.safe_load(File.read(path)), 'dir' => File.dirname(path))
        kase if kase['location'] == location && message.match?(Regexp.new(kase['message']))
      end
      refute_empty found, "no case of the error corpus is expected to print #{line}"
      found
    end

    def assert_link_resolves(doc, target, where)
      path, anchor = target.split('#', 2)
      source = File.join(GEM_ROOT, doc.path)
      file = path.empty? ? source : File.expand_path(path, File.dirname(source))
      assert file.start_with?("#{GEM_ROOT}/"), "#{where}: outside the gem"
      assert File.exist?(file), "#{where}: no such file"
      return unless anchor

      assert file.end_with?('.md'), "#{where}: an anchor into a file that is not Markdown"
      ids = Doc::Markdown.new(File.read(file)).headings.map(&:id)
      assert_includes ids, anchor, "#{where}: no such heading"
    end

    def assert_excerpt(lines, body, what)
      lines = lines.map { |l| code_of(l) }
      at = 0
      body.lines.map { |l| code_of(l) }.reject { |l| l.empty? || l.start_with?('#') }.each do |line|
        found = lines[at..].index(line)
        assert found, "#{what}: '#{line}' is not in the file (after line #{at})"
        at += found + 1
      end
    end

    def code_of(line)
      line.sub(/\s+# .*$/, '').strip
    end
  end
end
