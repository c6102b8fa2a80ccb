# frozen_string_literal: true

require 'helper'
require 'json'

module Syskit
  module Config
    # Process servers, the machines deployments run on: older Syskit's
    # Syskit.conf.process_server and today's register_process_server
    # declare them; use_deployment's on: says where each deployment runs,
    # and the plan says it too.
    class TestProcessServers < Minitest::Test
      ROBOT = <<~RUBY
        Syskit.conf.process_server 'front', 'front.local'
        Syskit.conf.register_process_server 'back', nil, '/tmp/logs', host_id: 'back.local'
        Syskit.conf.use_deployment OroGen.imu.Task => 'imu', on: 'front'
        Syskit.conf.use_deployment OroGen.temp.Task => 'temperature'
      RUBY
      DEVICES = "device(Devices::IMU, as: 'imu')\ndevice(Devices::TemperatureSensor, as: 'temperature')\n"

      def test_the_plan_says_where_each_deployment_runs
        root = my_app(DEVICES, 'config/robots/default.rb' => ROBOT)
        out, err, status = run_cli('plan', '--app', root)
        assert_equal 0, status, err
        assert_includes out, 'imu  imu::Task  (deployment imu on front (front.local), conf default)'
        assert_includes out, 'temperature  temp::Task  (deployment temperature, conf default)'
        tasks = JSON.parse(run_cli('plan', '--app', root, '--format', 'json').first)['tasks']
        assert_equal({ 'imu' => { 'name' => 'front', 'host' => 'front.local' }, 'temperature' => nil },
                     tasks.to_h { |t| [t['name'], t['process_server']] })
        assert_includes run_cli('plan', '--app', root, '--format', 'dot').first,
                        'imu::Task\\non\\ front\\ (front.local)'
        out, = run_cli('check', '--app', root)
        assert_equal "MyApp: 0 error(s), 0 warning(s)\n", out
        assert_site_says_where_imu_runs(root)
      end

      # The site's profile page lists the task's deployment with its server.
      def assert_site_says_where_imu_runs(root)
        site = File.join(root, 'site')
        _, err, status = run_cli('doc', '--app', root, '--output', site)
        assert_equal 0, status, err
        page = File.read(File.join(site, 'profiles', 'MyApp.Profiles.Base.html'))
        assert_includes page, '<code>imu</code> on front (front.local)</td>'
      end

      def test_a_deployment_on_a_process_server_that_is_not_declared
        robot = ROBOT.sub("on: 'front'", "on: 'rear'")
        root = my_app(DEVICES, 'config/robots/default.rb' => robot)
        out, err, status = run_cli('plan', '--app', root)
        assert_equal [1, ''], [status, out]
        assert_equal "config/robots/default.rb:3: no process server called 'rear' (declared: localhost, ruby_tasks, " \
                     "unmanaged_tasks, front, back)\n  hint: declare it before the deployments that run on it: " \
                     "Syskit.conf.process_server 'rear', 'hostname'\n", err
      end

      def test_a_process_server_declared_twice
        robot = "#{ROBOT}Syskit.conf.process_server 'front', 'other.local'\n"
        root = my_app(DEVICES, 'config/robots/default.rb' => robot)
        _, err, status = run_cli('plan', '--app', root)
        assert_equal 1, status
        assert_match(%r{\Aconfig/robots/default.rb:5: there is already a process server called 'front' at }, err)
      end
    end
  end
end
