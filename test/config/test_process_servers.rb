# frozen_string_literal: true

require 'helper'

module Syskit
  module Config
    # Process servers, the machines deployments run on: older Syskit's
    # Syskit.conf.process_server and today's register_process_server are
    # accepted with a "not modelled" warning (and use_deployment's on:
    # ignored), rather than failing the whole robot configuration.
    class TestProcessServers < Minitest::Test
      ROBOT = <<~RUBY
        Syskit.conf.process_server 'front', 'localhost'
        Syskit.conf.register_process_server 'back', nil, '/tmp/logs'
        Syskit.conf.use_deployment OroGen.imu.Task => 'imu', on: 'front'
      RUBY

      def test_the_robot_configuration_loads_and_plans
        root = my_app("device(Devices::IMU, as: 'imu')\n", 'config/robots/default.rb' => ROBOT)
        out, err, status = run_cli('plan', '--app', root)
        assert_equal 0, status, err
        assert_includes out, 'imu  imu::Task  (deployment imu'
        out, _, status = run_cli('check', '--app', root)
        assert_equal 0, status, out
        assert_includes out, 'config/robots/default.rb:1: warning: Syskit.conf.process_server: not modelled'
        assert_includes out, 'config/robots/default.rb:2: warning: Syskit.conf.register_process_server: not modelled'
      end
    end
  end
end
