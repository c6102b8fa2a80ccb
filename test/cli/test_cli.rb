# frozen_string_literal: true

require 'helper'
require 'json'
require 'open3'
require 'rbconfig'

module Syskit
  # bin/syskit as users run it (SPEC 10).
  class TestCLI < Minitest::Test
    extend SelfTest::Long

    EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')
    BACKTRACE = /\.rb:\d+:in `/

    def test_version_and_help
      out, = run_cli('version')
      assert_equal "syskit #{VERSION}\n#{ABOUT}, from #{GEM_ROOT}\n", out
      out, = run_cli('help', 'plan')
      assert_match(/Example: syskit plan Live::Base temperature_sensor_dev --format json/, out)
    end

    # Outside an app, every command says so, as gen does, rather than
    # working on the gem's example app.
    def test_commands_outside_an_app_say_so
      outside = Dir.mktmpdir('syskit-outside')
      [%w[plan], %w[check], %w[doc], %w[bus timing], %w[test]].each do |command|
        out, err, status = run_cli(*command, chdir: outside)
        assert_equal [1, ''], [status, out], command.join(' ')
        assert_match(/\A#{Regexp.escape(outside)} is not in a Syskit app\n  hint: pass --app DIR, or cd into an app/,
                     err, command.join(' '))
      end
    ensure
      FileUtils.rm_rf(outside)
    end

    def test_plan_uses_the_app_of_the_current_directory
      out, err, status = run_cli('plan', chdir: fixture('seed', 'can_bus', 'models'))
      assert_equal 0, status, err
      assert_match(/^Plan of MyApp::Profiles::Base/, out)
    end

    def test_plan_of_a_profile_by_short_name_and_actions
      out, err, status = run_cli('plan', 'Live::Base', 'gps_dev', 'can0', '--app', EXAMPLE, '--format', 'json')
      assert_equal 0, status, err
      assert_equal(%w[can0 gps], JSON.parse(out)['tasks'].map { |t| t['name'] })
    end

    def test_plan_takes_the_path_form_of_gen_profile
      out, err, status = run_cli('plan', 'live/base', '--app', EXAMPLE)
      assert_equal 0, status, err
      assert_match(/\APlan of AwesomeRobot::Profiles::Live::Base /, out)
      _, err, = run_cli('plan', 'live/bsae', '--app', EXAMPLE)
      assert_match(%r{\Ano profile named 'live/bsae' \(did you mean 'live/base'\?\)}, err)
    end

    # Right after gen app and gen profile live/base, Base is Profiles::Base;
    # a name several profiles end with lists the names to type.
    def test_a_profile_name_several_profiles_end_with
      app = write_app({ 'config/syskit.yml' => "name: Bot\n", 'config/robots/default.rb' => '' }, name: 'bot')
      %w[base live/base sim/base sim/other/base].each { |name| run_cli('gen', 'profile', name, chdir: app) }
      out, err, status = run_cli('plan', 'Base', '--app', app)
      assert_equal 0, status, err
      assert_match(/\APlan of Bot::Profiles::Base /, out)
      FileUtils.rm(File.join(app, 'models', 'profiles', 'base.rb'))
      out, err, status = run_cli('plan', 'Base', '--app', app)
      assert_equal [1, ''], [status, out]
      assert_equal "'Base' names several profiles: Bot::Profiles::Live::Base, Bot::Profiles::Sim::Base, " \
                   "Bot::Profiles::Sim::Other::Base\n  hint: type one of Live::Base, Sim::Base, Other::Base\n", err
    end

    # The app's models live as long as the process: they load with the
    # garbage collector off (fewer full collections at 10,000 devices),
    # which runs again for the command itself.
    GC_OFF_WHILE_LOADING = [] # rubocop:disable Style/MutableConstant -- filled by the app's robot file
    def test_the_app_loads_with_the_garbage_collector_off
      robot = "Syskit::TestCLI::GC_OFF_WHILE_LOADING << GC.disable\n"
      app = write_app({ 'config/syskit.yml' => "name: Bot\n", 'config/robots/default.rb' => robot }, name: 'bot')
      run_cli('gen', 'profile', 'base', chdir: app)
      _, err, status = run_cli('plan', '--app', app)
      assert_equal 0, status, err
      assert_equal [true], GC_OFF_WHILE_LOADING
      refute GC.enable, 'the collector is on again after loading'
    ensure
      GC.enable
    end

    def test_plan_without_a_profile_when_the_first_has_no_device
      arm = "module MyApp\n  module Profiles\n    profile('Arm') { robot {} }\n  end\nend\n"
      root = my_app("device MyApp::Devices::IMU, as: 'imu'", 'models/profiles/arm.rb' => arm)
      out, err, status = run_cli('plan', '--app', root)
      assert_equal [1, ''], [status, out]
      assert_equal "MyApp::Profiles::Arm, the app's first profile, has no device\n  hint: name the profile to plan: " \
                   "MyApp::Profiles::Base (e.g. syskit plan MyApp::Profiles::Base)\n", err
    end

    # The bus tools pick the first profile as plan does: their hint runs
    # them, not plan.
    def test_bus_timing_without_a_profile_when_the_first_has_no_device
      arm = "module MyApp\n  module Profiles\n    profile('Arm') { robot {} }\n  end\nend\n"
      root = my_app("device MyApp::Devices::IMU, as: 'imu'", 'models/profiles/arm.rb' => arm)
      _, err, status = run_cli('bus', 'timing', '--app', root)
      assert_equal 1, status
      assert_includes err, '(e.g. syskit bus timing MyApp::Profiles::Base)'
    end

    # A profile with nothing to plan plans, and says so at its declaration.
    def test_the_plan_of_an_empty_profile_says_it_is_empty
      root = my_app('', 'models/profiles/base.rb' => "module MyApp\n  module Profiles\n    " \
                                                     "profile('Base') { robot {} }\n  end\nend\n")
      out, err, status = run_cli('plan', 'Base', '--app', root)
      assert_equal 0, status, err
      assert_match(/^Tasks \(0\)$/, out)
      assert_equal 'models/profiles/base.rb:3: warning: MyApp::Profiles::Base has no device and no definition: its ' \
                   "plan is empty\n  hint: declare the robot's devices in its robot block\n", err
    end

    def test_unknown_profile
      _, err, status = run_cli('plan', 'Bsae', '--app', EXAMPLE)
      assert_equal 1, status
      assert_equal "no profile named 'Bsae'\n  hint: profiles: AwesomeRobot::Profiles::Live::Base\n", err
    end

    def test_errors_are_one_located_message_with_a_hint_and_no_backtrace
      root = my_app("device(Devices::IMU, as: 'imu')\n", 'config/robots/default.rb' => "# nothing\n")
      out, err, status = run_cli('plan', '--app', root)
      assert_equal 1, status
      assert_empty out
      lines = err.lines
      assert_equal "models/profiles/base.rb:9: no deployed task can run imu::Task, the driver of device 'imu', " \
                   "on robot 'default'\n", lines[0]
      assert_match(/\A  hint: add to config/, lines[1])
      refute_match BACKTRACE, err
      _, err, = run_cli('plan', '--app', root, '--trace')
      assert_match BACKTRACE, err
    end

    def test_an_unknown_robot_configuration
      _, err, status = run_cli('plan', '--app', EXAMPLE, '--robot', 'sim')
      assert_equal 1, status
      assert_match(%r{\Aconfig/robots/sim.rb: no configuration for robot 'sim'}, err)
    end

    def test_check_passes_on_the_example_app
      out, err, status = run_cli('check', '--app', EXAMPLE)
      assert_equal 0, status, "#{out}#{err}"
      assert_equal "AwesomeRobot: 0 error(s), 0 warning(s)\n", out
    end

    OVERLAP = <<~RUBY
      com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
      through 'can0' do
        device(Devices::TemperatureSensor, as: 'a').can_id(0x100, 0x700)
        device(Devices::TemperatureSensor, as: 'b').can_id(0x120, 0x7f0)
        device(Devices::TemperatureSensor, as: 'c').can_id(0x200, 0x7ff)
      end
    RUBY

    # Deploys the bus, and a temp::Task for each of the devices a, b and c.
    EVERY_DEVICE_DEPLOYED = "using_task_library 'temp'\nSyskit.conf.use_deployment 'test_canbus'\n" \
                            "%w[a b c].each { |n| Syskit.conf.use_deployment OroGen.temp.Task => n }\n"

    def overlap_app
      my_app("#{OVERLAP}device(Devices::IMU, as: 'imu', using: OroGen.temp.Task)\n",
             'config/robots/default.rb' => "Syskit.conf.use_deployment 'test_canbus'\n",
             'config/robots/sim.rb' => "Syskit.conf.use_deployment 'test_canbus'\n")
    end

    def test_check_reports_every_problem_grouped_by_file_with_a_count
      out, _, status = run_cli('check', '--app', overlap_app)
      assert_equal 1, status
      lines = out.lines
      assert_match(Regexp.new('\Amodels/profiles/base.rb:12: warning: device \'a\' \(id 0x100 mask 0x700\) and ' \
                              'device \'b\' \(id 0x120 mask 0x7F0\) on bus \'can0\' have overlapping filters'),
                   lines[0])
      assert_match(/^  hint: narrow one of the masks/, lines[1])
      assert_match(%r{^models/profiles/base.rb:15: temp::Task does not drive MyApp::Devices::IMU}, out)
      assert_equal "MyApp: 1 error(s), 1 warning(s)\n", lines.last
      refute_match BACKTRACE, out
    end

    def test_standard_and_extended_filters_never_overlap
      robot = <<~RUBY
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through 'can0' do
          device(Devices::TemperatureSensor, as: 'a').can_id(0x120, 0x7ff).prefer_deployed_tasks('a')
          device(Devices::TemperatureSensor, as: 'b').can_id(0x120, 0x1fffffff).prefer_deployed_tasks('b')
          device(Devices::TemperatureSensor, as: 'c').can_id(0x120, 0xfff).prefer_deployed_tasks('c')
        end
      RUBY
      root = my_app(robot, 'config/robots/default.rb' => EVERY_DEVICE_DEPLOYED)
      out, = run_cli('check', '--app', root)
      assert_match(/device 'b' \(id 0x120 mask 0x1FFFFFFF\) and device 'c' .* have overlapping filters/, out)
      refute_match(/device 'a' .* overlapping/, out)
      assert_match(/0 error\(s\), 1 warning\(s\)/, out)
    end

    def test_check_json_and_strict
      robot = OVERLAP.gsub(/as: '(\w)'\)(.*)$/) do
        name, rest = Regexp.last_match.captures
        "as: '#{name}')#{rest}.prefer_deployed_tasks('#{name}')"
      end
      root = my_app(robot, 'config/robots/default.rb' => EVERY_DEVICE_DEPLOYED)
      out, err, status = run_cli('check', '--app', root)
      assert_equal 0, status, "#{out}#{err}"
      assert_match(/0 error\(s\), 1 warning\(s\)/, out)
      out, _, status = run_cli('check', '--app', root, '--strict')
      assert_equal 1, status
      assert_match(%r{^models/profiles/base.rb:12: device '\w' .* have overlapping filters}, out)
      refute_match(/warning:/, out)
      assert_match(/1 error\(s\), 0 warning\(s\)/, out)
      out, = run_cli('check', '--app', root, '--format', 'json')
      doc = JSON.parse(out)
      assert_equal [0, 1], doc.values_at('errors', 'warnings')
      assert_equal({ 'file' => 'models/profiles/base.rb', 'line' => 12, 'severity' => 'warning' },
                   doc['problems'].first.slice('file', 'line', 'severity'))
    end

    def test_problems_are_coloured_on_a_terminal_only
      root = my_app("device MyApp::Devices::IMU, as: 'imu'\ndevice MyApp::Devices::IMUU, as: 'imu2'")
      plain, = run_cli('check', '--app', root)
      refute_match(/\e\[/, plain)
      coloured = on_terminal('check', '--app', root)
      assert_match(%r{\e\[1mmodels/profiles/base.rb:10\e\[0m: \e\[31m.*IMUU}, coloured)
      assert_match(/^  \e\[36mhint:\e\[0m /, coloured)
      refute_match(/\e\[/, on_terminal('check', '--app', root, env: { 'NO_COLOR' => '1' }))
    end

    def test_exit_status_of_the_real_executable
      _, err, status = syskit_process('plan', 'Nope', '--app', EXAMPLE)
      assert_equal 1, status.exitstatus
      assert_match(/no profile named 'Nope'/, err)
    end

    # syskit/cli.rb loads the command line only; each command loads what
    # it needs when it runs: each works in a process of its own.
    def test_each_command_loads_what_it_needs
      out, err, status = syskit_process('--version')
      assert_equal [0, "syskit #{VERSION}\n#{ABOUT}, from #{GEM_ROOT}\n", ''], [status.exitstatus, out, err]
      Dir.mktmpdir do |dir|
        plan = File.join(dir, 'plan.json')
        File.write(plan, syskit_process('plan', '--app', EXAMPLE, '--format', 'json').first)
        out, err, status = syskit_process('plan', '--app', EXAMPLE, '--diff', plan)
        assert_equal 0, status.exitstatus, err
        assert_match(/^the plans are the same$/, out)
        out, err, status = syskit_process('diff', plan, plan)
        assert_equal 0, status.exitstatus, err
        assert_match(/^the plans are the same$/, out)
      end
    end

    # What the help and the version print needs no model: they load none.
    def test_help_and_version_load_no_model
      [%w[help], %w[help plan], %w[gen help dev], %w[--version], %w[plna]].each do |args|
        script = "ARGV.replace(#{args.inspect}); " \
                 "at_exit { warn \"model layer: \#{defined?(Syskit::App).inspect}\" }; " \
                 "load #{File.join(GEM_ROOT, 'bin', 'syskit').inspect}"
        out, err, = Open3.capture3(SelfTest.child_env, RbConfig.ruby, '-e', script, unsetenv_others: true)
        assert_match(/syskit/, out + err, args)
        assert_match(/^model layer: nil$/, err, args)
      end
    end

    private

    # What syskit writes on a terminal (a pseudo-terminal: stdout and
    # stderr together).
    def on_terminal(*args, env: {})
      require 'pty'
      out = +''
      PTY.spawn(SelfTest.child_env.merge(env), RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), *args,
                unsetenv_others: true) do |reader, _, pid|
        begin
          reader.each_line { |l| out << l }
        rescue Errno::EIO
          # the terminal closes when syskit exits
        end
        Process.wait(pid)
      end
      out
    end
  end
end
