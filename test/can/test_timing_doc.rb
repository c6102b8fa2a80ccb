# frozen_string_literal: true

require 'docs_helper'

module Syskit
  # What the CAN bus timing guide shows is what the commands print.
  class TestTimingDoc < Minitest::Test
    DOC = SelfTest::Docs.guide('can-timing')
    COMMAND = 'bundle exec bin/syskit '

    def examples
      DOC.commands(COMMAND)
    end

    def test_every_example_is_what_the_command_prints
      assert_equal 3, examples.size
      examples.each do |command, shown|
        out, err, status = run_cli(*command.split)
        assert_equal command.start_with?('check') ? 1 : 0, status, err
        assert_equal shown, out, command
      end
    end

    def test_the_declarations_shown_are_the_example_apps
      profile = File.read(File.join(GEM_ROOT, 'examples/awesome_robot/models/profiles/live/base.rb'))
      DOC.code_block('ruby').lines.grep(/\.frame|\.bitrate/).each do |line|
        assert_includes profile, line.sub(/ +#.*/, '').strip, 'the guide shows the example app'
      end
    end
  end
end
