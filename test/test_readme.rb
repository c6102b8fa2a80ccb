# frozen_string_literal: true

require 'helper'

module Syskit
  # What the README claims is what the commands show.
  class TestReadme < Minitest::Test
    README = File.read(File.join(GEM_ROOT, 'README.md'))
    EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')

    def test_it_starts_with_the_two_setup_commands
      commands = README[/```sh\n(.*?)```/m, 1].lines.map(&:strip)
      assert_equal ['bundle install && bundle exec bin/syskit plan --app examples/awesome_robot',
                    'bundle install && bundle exec rake test'], commands
      # CI installs, checks the style, then runs the README's test command.
      ci = File.read(File.join(GEM_ROOT, '.ci', 'run')).lines.map(&:strip).grep(/\Abundle /)
      assert_equal ['bundle install', 'bundle exec rake lint', 'bundle exec rake test'], ci
    end

    def test_the_error_corpus_count_is_the_number_of_cases
      said = README[%r{under `test/fixtures/broken/` \(one broken app per case, (\d+)\s}, 1]
      refute_nil said, "the README no longer gives the corpus's size"
      cases = Dir.children(File.join(GEM_ROOT, 'test', 'fixtures', 'broken'))
                 .count { |c| File.directory?(File.join(GEM_ROOT, 'test', 'fixtures', 'broken', c)) }
      assert_equal cases, Integer(said)
    end

    # The tour's snippets headed by a file of the example app are excerpts
    # of that file: each line, in order (comments after code aside).
    def test_the_tour_snippets_are_excerpts_of_the_example_app
      snippets = README.scan(/^```(?:ruby|yaml)\n# (\S+\.(?:rb|yml|orogen))(?: \([^)\n]*\))?\n(.*?)^```/m)
      assert_operator snippets.size, :>=, 8
      snippets.each do |path, body|
        file = File.join(EXAMPLE, path)
        assert File.file?(file), "README's snippet of #{path}: the example app has no such file"
        lines = File.readlines(file).map { |l| code_of(l) }
        at = 0
        body.lines.map { |l| code_of(l) }.reject { |l| l.empty? || l.start_with?('#') }.each do |line|
          found = lines[at..].index(line)
          assert found, "README's snippet of #{path}: '#{line}' is not in the file (after line #{at})"
          at += found + 1
        end
      end
    end

    def test_the_example_plan_is_the_one_the_command_prints
      shown = README[%r{^\$ bundle exec bin/syskit plan --app examples/awesome_robot\n(.*?)^```}m, 1]
      out, err, status = run_cli('plan', '--app', 'examples/awesome_robot')
      assert_equal 0, status, err
      assert_equal out, shown
    end

    private

    def code_of(line)
      line.sub(/\s+# .*$/, '').strip
    end
  end
end
