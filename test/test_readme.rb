# frozen_string_literal: true

require 'docs_helper'

module Syskit
  # What the README claims is what the commands show (the guides' own
  # snippets: test_docs.rb and the tests of each topic).
  class TestReadme < Minitest::Test
    include SelfTest::Docs::Assertions

    README = SelfTest::Docs.readme

    def test_it_starts_with_the_two_setup_commands
      commands = README.code_block('sh').lines.map(&:strip)
      assert_equal ['bundle install && bundle exec bin/syskit plan --app examples/awesome_robot',
                    'bundle install && bundle exec rake test'], commands
      # CI installs, checks the style, then runs the README's test command.
      ci = File.read(File.join(GEM_ROOT, '.ci', 'run')).lines.map(&:strip).grep(/\Abundle /)
      assert_equal ['bundle install', 'bundle exec rake lint', 'bundle exec rake test'], ci
    end

    def test_the_version_shown_is_what_the_command_prints
      shown = README.output_of('syskit version')
      out, err, status = run_cli('version')
      assert_equal 0, status, err
      assert_equal shown, out.sub(/ from #{Regexp.escape(GEM_ROOT)}$/, ' from /path/of/the/gem')
                             .sub(/\Asyskit #{Regexp.escape(VERSION)}$/, 'syskit 0.1.0')
    end

    # The tour's plan is an excerpt of what the command prints.
    def test_the_tour_plan_is_an_excerpt_of_what_the_command_prints
      shown = README.output_of('bundle exec bin/syskit plan --app examples/awesome_robot')
      out, err, status = run_cli('plan', '--app', 'examples/awesome_robot')
      assert_equal 0, status, err
      assert_operator assert_shown_excerpt(shown, out, "the README's plan"), :>=, 5
    end
  end
end
