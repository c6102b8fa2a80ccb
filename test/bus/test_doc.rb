# frozen_string_literal: true

require 'docs_helper'
require 'json'

module Syskit
  # What the bus traffic guide shows is what the commands print.
  class TestBusDoc < Minitest::Test
    DOC = SelfTest::Docs.guide('bus-tools')
    COMMAND = 'bundle exec bin/syskit '

    # The output shown under "$ COMMAND", and the command's arguments.
    def example(command)
      [command.split, DOC.output_of(COMMAND + command)]
    end

    def test_the_replay_example
      args, shown = example('bus replay Live::Base --bus can0 examples/awesome_robot/logs/can0.log ' \
                            '--app examples/awesome_robot')
      out, err, status = run_cli(*args)
      assert_equal 0, status, err
      assert_equal shown, out
    end

    def test_the_strict_example
      args, shown = example('bus replay Live::Base --bus can0 examples/awesome_robot/logs/can0.log ' \
                            '--app examples/awesome_robot --strict')
      _, err, status = run_cli(*args)
      assert_equal 1, status
      assert_equal shown, err
    end

    def test_the_json_example
      shown = JSON.parse(DOC.code_block('json'))
      out, = run_cli('bus', 'replay', 'Live::Base', '--bus', 'can0', 'examples/awesome_robot/logs/can0.log',
                     '--app', 'examples/awesome_robot', '--format', 'json')
      n2k = JSON.parse(out)['devices'].find { |d| d['name'] == 'n2k' }
      assert_equal shown, n2k
    end

    def test_the_missing_interface_example
      args, shown = example('bus monitor Live::Base --bus can0 --interface vcan0 --app examples/awesome_robot')
      skip 'this machine has a vcan0 interface' if File.exist?('/sys/class/net/vcan0')

      _, err, status = run_cli(*args)
      assert_equal 1, status
      # The hint lists the machine's CAN interfaces, if it has any.
      assert_equal shown.lines.first, err.lines.first
    end
  end
end
