# frozen_string_literal: true

require 'helper'

module Syskit
  # What the README claims is what the commands show.
  class TestReadme < Minitest::Test
    README = File.read(File.join(GEM_ROOT, 'README.md'))

    def test_it_starts_with_the_two_setup_commands
      commands = README[/```sh\n(.*?)```/m, 1].lines.map(&:strip)
      assert_equal ['bundle install && bundle exec bin/syskit plan --app examples/awesome_robot',
                    'bundle install && bundle exec rake test'], commands
      assert_equal 'bundle install && bundle exec rake test',
                   File.read(File.join(GEM_ROOT, '.ci', 'run')).lines.last.strip
    end

    def test_the_example_plan_is_the_one_the_command_prints
      shown = README[%r{^\$ bundle exec bin/syskit plan --app examples/awesome_robot\n(.*?)^```}m, 1]
      out, err, status = run_cli('plan', '--app', 'examples/awesome_robot')
      assert_equal 0, status, err
      assert_equal out, shown
    end
  end
end
