# frozen_string_literal: true

require 'docs_helper'
require 'json'

module Syskit
  # `syskit plan --diff OLD.json` and `syskit diff OLD.json NEW.json`: a
  # change to a robot, as a reviewer reads it.
  class TestDiffCLI < Minitest::Test
    ROBOT = <<~RUBY
      com_bus(CommonModels::Devices::Bus::CAN, as: 'can0', using: OroGen.canbus.Task)
      through 'can0' do
        device(Devices::TemperatureSensor, as: 'sensor').can_id(0x100, 0x7ff).prefer_deployed_tasks('sensor')
      end
      device(Devices::IMU, as: 'imu')
    RUBY
    # The sensor's filter changes, a second sensor comes, the IMU goes.
    CHANGED = <<~RUBY
      com_bus(CommonModels::Devices::Bus::CAN, as: 'can0', using: OroGen.canbus.Task)
      through 'can0' do
        device(Devices::TemperatureSensor, as: 'sensor').can_id(0x101, 0x7ff).prefer_deployed_tasks('sensor')
        device(Devices::TemperatureSensor, as: 'sensor2').can_id(0x200, 0x7ff).prefer_deployed_tasks('sensor2')
      end
    RUBY
    DEPLOYMENTS = <<~RUBY
      using_task_library 'imu'
      Syskit.conf.use_deployment OroGen.imu.Task => 'imu'
      Syskit.conf.use_deployment OroGen.canbus.Task => 'can0'
      Syskit.conf.use_deployment OroGen.temp.Task => 'sensor'
      Syskit.conf.use_deployment OroGen.temp.Task => 'sensor2'
    RUBY

    # What the reviewer of the change reads.
    EXPECTED = <<~TEXT
      Plan diff of MyApp::Profiles::Base on robot 'default'
        old: old.json
        new: syskit plan MyApp::Profiles::Base

      Tasks: 1 added, 1 removed, 1 changed
        + sensor2  temp::Task, deployment sensor2
        - imu  imu::Task, deployment imu
        ~ can0
            ports.sensor2: added {"direction":"output","type":"/canbus/Message","dynamic":true}
            operations: watch("sensor", 0x100, 0x7FF) -> watch("sensor", 0x101, 0x7FF), watch("sensor2", 0x200, 0x7FF)

      Devices: 1 added, 1 removed, 1 changed
        + sensor2  MyApp::Devices::TemperatureSensor, task sensor2, bus can0
        - imu  MyApp::Devices::IMU, task imu
        ~ sensor
            attributes.can_id: [0x100,0x7FF] -> [0x101,0x7FF]

      Connections: 2 added
        + can0.sensor2 -> sensor2.can_in  /canbus/Message, buffer 20
        + sensor2.can_out -> can0.in  /canbus/Message, buffer 20

      Order: 2 added, 2 removed
        + configure sensor2
        + start sensor2
        - configure imu
        - start imu
    TEXT

    def setup
      super
      @app = my_app(ROBOT, 'config/robots/default.rb' => DEPLOYMENTS)
      out, err, status = run_cli('plan', '--format', 'json', '--app', @app)
      assert_equal 0, status, err
      @old = File.join(@app, 'old.json')
      File.write(@old, out)
      profile = File.join(@app, 'models', 'profiles', 'base.rb')
      File.write(profile, File.read(profile).sub(ROBOT.lines.map { |l| "        #{l}" }.join,
                                                 CHANGED.lines.map { |l| "        #{l}" }.join))
    end

    def test_plan_diff_says_what_changed
      out, err, status = run_cli('plan', '--diff', 'old.json', chdir: @app)
      assert_equal [0, EXPECTED], [status, out], err
      # Compared with itself, the new plan has no difference; --exit-code
      # makes a difference exit status 1.
      out, = run_cli('plan', '--format', 'json', chdir: @app)
      File.write(File.join(@app, 'new.json'), out)
      out, _, status = run_cli('plan', '--diff', 'new.json', chdir: @app)
      assert_equal [0, "the plans are the same\n"], [status, out.lines.last]
      assert_equal 0, run_cli('plan', '--diff', 'new.json', '--exit-code', chdir: @app).last
      assert_equal 1, run_cli('plan', '--diff', 'old.json', '--exit-code', chdir: @app).last
    end

    # Runs syskit ARGS in the app, which must succeed; returns its output.
    def syskit!(*args)
      out, err, status = run_cli(*args, chdir: @app)
      assert_equal 0, status, "syskit #{args.join(' ')}: #{err}"
      out
    end

    def test_diff_of_two_plan_files_in_text_and_json
      File.write(File.join(@app, 'new.json'), syskit!('plan', '--format', 'json'))
      assert_equal EXPECTED.sub('new: syskit plan MyApp::Profiles::Base', 'new: new.json'),
                   syskit!('diff', 'old.json', 'new.json')

      doc = JSON.parse(syskit!('diff', 'old.json', 'new.json', '--format', 'json'))
      assert_equal %w[old new identical lists], doc.keys
      assert_equal %w[tasks devices connections order buses compositions], doc['lists'].keys
      tasks = doc['lists']['tasks']
      assert_equal([['sensor2'], ['imu']], %w[added removed].map { |k| tasks[k].map { |t| t['name'] } })
      assert_equal({ 'path' => %w[ports sensor2], 'old' => nil,
                     'new' => { 'name' => 'sensor2', 'direction' => 'output', 'type' => '/canbus/Message',
                                'dynamic' => true } }, tasks['changed'].first['changes'].first)
      assert_equal 1, run_cli('diff', 'old.json', 'new.json', '--exit-code', chdir: @app).last
    end

    # One watch call of several changes: it alone is shown, with its
    # position, ids in hex as in the plan.
    def test_one_changed_operation_call_is_shown_alone
      File.write(@old, syskit!('plan', '--format', 'json'))
      profile = File.join(@app, 'models', 'profiles', 'base.rb')
      File.write(profile, File.read(profile).sub('can_id(0x200, 0x7ff)', 'can_id(0x280, 0x7ff)'))
      out = syskit!('plan', '--diff', 'old.json')
      changed = 'operations.2: watch("sensor2", 0x200, 0x7FF) -> watch("sensor2", 0x280, 0x7FF)'
      assert_includes out, "  ~ can0\n      #{changed}\n"
      refute_includes out, 'watch("sensor",'
    end

    # The plan guide's example, on a copy of the example app.
    def test_the_example_of_the_plan_guide
      shown = SelfTest::Docs.guide('plan').section('Reviewing a change: plan diffs')
                            .output_of('syskit plan Live::Base --diff plan.json')
      app = File.join(Dir.mktmpdir('syskit-diff'), 'awesome_robot')
      (@tmpdirs ||= []) << File.dirname(app)
      FileUtils.cp_r(File.join(GEM_ROOT, 'examples', 'awesome_robot'), app)
      out, = run_cli('plan', 'Live::Base', '--format', 'json', chdir: app)
      File.write(File.join(app, 'plan.json'), out)
      profile = File.join(app, 'models', 'profiles', 'live', 'base.rb')
      File.write(profile, File.read(profile).sub("as: 'right_motor')\n              .can_id(0x182, 0x7ff)",
                                                 "as: 'right_motor')\n              .can_id(0x183, 0x7ff)")
                                            .sub('.bitrate(1_000_000)', '.bitrate(500_000)'))
      out, err, status = run_cli('plan', 'Live::Base', '--diff', 'plan.json', chdir: app)
      assert_equal [0, shown], [status, out]
      assert_match(/\Abus 'can1': 4 frames of 6 can miss their deadline/, err)
    end

    # A definition's argument changes; a composition the old plan did not
    # have is added.
    def test_compositions_are_compared_by_name
      app = File.join(Dir.mktmpdir('syskit-diff'), 'awesome_robot')
      (@tmpdirs ||= []) << File.dirname(app)
      FileUtils.cp_r(File.join(GEM_ROOT, 'examples', 'awesome_robot'), app)
      old = JSON.parse(run_cli('plan', 'Live::Base', '--format', 'json', chdir: app).first)
      old['compositions'].reject! { |c| c['name'] == 'watch_temperatures' }
      File.write(File.join(app, 'plan.json'), JSON.generate(old))
      profile = File.join(app, 'models', 'profiles', 'live', 'base.rb')
      File.write(profile, File.read(profile).sub('with_arguments(max_speed: 0.5)', 'with_arguments(max_speed: 0.8)'))
      out, err, status = run_cli('plan', 'Live::Base', '--diff', 'plan.json', chdir: app)
      assert_equal 0, status, err
      # The argument reaches the child's property through its configure.
      assert_includes out, "Tasks: 1 changed\n  ~ path_follower\n      properties.max_speed: 0.5 -> 0.8\n"
      assert_includes out, "Compositions: 1 added, 1 changed\n  " \
                           '+ watch_temperatures  AwesomeRobot::Compositions::TemperatureWatch, ' \
                           "children temperature_sensor water_temperature temperature_monitor\n  " \
                           "~ drive\n      arguments.max_speed: 0.5 -> 0.8\n"
    end

    # What follows is the JSON parser's own words, which its versions change.
    NOT_JSON = /\Abroken\.json: this is not a JSON plan: (unexpected|expected).*\n  hint: a plan file is/

    def test_files_that_are_not_plans
      File.write(File.join(@app, 'empty.json'), '')
      File.write(File.join(@app, 'broken.json'), '{"tasks": [')
      File.write(File.join(@app, 'other.json'), '{"name": "x"}')
      hint = "\n  hint: a plan file is what syskit plan PROFILE --format json > plan.json writes\n"
      { %w[diff nothing.json old.json] => "no plan file 'nothing.json'#{hint}",
        %w[diff old.json empty.json] => "empty.json: this plan file is empty#{hint}",
        %w[plan --diff broken.json] => NOT_JSON,
        %w[diff other.json old.json] => 'other.json: this is JSON but not a plan (it has no profile, robot and ' \
                                        "tasks)#{hint}",
        %w[plan --diff old.json --format dot] => "--diff prints the difference as text or json, not dot\n  " \
                                                 "hint: leave out --format, or give --format json\n" }
        .each do |args, message|
          out, err, status = run_cli(*args, chdir: @app)
          assert_equal [1, ''], [status, out], "syskit #{args.join(' ')}"
          message.is_a?(String) ? assert_equal(message, err) : assert_match(message, err)
        end
    end
  end
end
