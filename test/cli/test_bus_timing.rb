# frozen_string_literal: true

require 'helper'
require 'json'

module Syskit
  # `syskit bus timing`: the analysis of a profile's CAN bus, for people and
  # programs.
  class TestBusTimingCLI < Minitest::Test
    EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')

    def timing(*args)
      run_cli('bus', 'timing', *args)
    end

    def test_a_table_in_priority_order
      out, err, status = timing('Live::Base', '--bus', 'can1', '--app', EXAMPLE)
      assert_equal 0, status, err
      lines = out.lines
      assert_equal "Bus can1 of AwesomeRobot::Profiles::Live::Base: 1 Mbit/s, utilisation 54.1 %\n", lines.first
      assert_equal %w[ID Device Bytes Period Deadline Jitter C Blocking Response Slack], lines[3].split
      assert_equal(%w[181 182 201 202 701 702], lines[4..9].map { |l| l.split.first })
      # 0x202: blocked by a heartbeat (65 us), after three 135 us frames and
      # its own 0.2 ms of jitter.
      assert_equal %w[202 right_motor 8 1.000 1.000 0.200 0.135 0.065 0.805 0.195 ok], lines[7].split
      assert_equal "every frame meets its deadline (6 frames)\n", lines.last
    end

    # The plan is printed, and stderr says its bus's frames can be late.
    def test_plan_says_when_frames_can_miss_their_deadline
      out, err, status = run_cli('plan', '--app', fixture('broken', 'can_frame_misses_deadline'))
      assert_equal 0, status
      assert_match(/^Plan of MyApp::Profiles::Base/, out)
      assert_equal "bus 'can0': 1 frame of 3 can miss its deadline (syskit bus timing MyApp::Profiles::Base " \
                   "--bus can0 shows which)\n", err
      _, err, = run_cli('plan', '--app', fixture('broken', 'can_bus_overloaded'))
      assert_match(/\Abus 'can0': 1 frame of 1 can miss its deadline/, err)
      _, err, = run_cli('plan', '--app', EXAMPLE)
      assert_empty err
    end

    # As plan does, without PROFILE the app's first profile.
    def test_the_first_profile_by_default
      out, err, status = timing('--bus', 'can1', '--app', EXAMPLE)
      assert_equal 0, status, err
      assert_equal timing('Live::Base', '--bus', 'can1', '--app', EXAMPLE).first, out
    end

    def test_json
      out, err, status = timing('Live::Base', '--bus', 'can0', '--app', EXAMPLE, '--format', 'json')
      assert_equal 0, status, err
      doc = JSON.parse(out)
      assert_equal %w[bus bitrate utilization schedulable frames], doc.keys
      assert_equal ['can0', 250_000, 0.03114, true], doc.values_at('bus', 'bitrate', 'utilization', 'schedulable')
      sync = doc['frames'][1]
      assert_equal %w[id extended bytes device period deadline jitter transmission_time blocking response_time slack
                      schedulable stopped_at_miss], sync.keys
      # 55 bits of 4 us; blocked by the 8-byte NMEA 2000 frame; after the
      # temperature frame, whose extended id has base id 0.
      assert_equal [0x80, 0.00022, 0.00064, 0.00136], sync.values_at('id', 'transmission_time', 'blocking',
                                                                     'response_time')
    end

    # Davis et al.'s example, the third frame due in 3.25 ms.
    PAPER = <<~RUBY
      com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(135_000)
      through 'can0' do
        device(Devices::TemperatureSensor, as: 'a').can_id(1).frame(1, bytes: 8, period: 0.0025)
        device(Devices::TemperatureSensor, as: 'b').can_id(2).frame(2, bytes: 8, period: 0.0035)
        device(Devices::TemperatureSensor, as: 'c').can_id(3).frame(3, bytes: 8, period: 0.0035, deadline: 0.00325)
      end
    RUBY

    def test_a_frame_that_can_miss_its_deadline
      root = my_app(PAPER)
      out, err, status = timing('Base', '--app', root)
      assert_equal 1, status, err
      assert_equal %w[003 c 8 3.500 3.250 0.000 1.000 0.000 3.500 -0.250 MISS], out.lines[6].split
      assert_equal "1 of 3 frames can miss its deadline\n", out.lines.last
      json, = timing('Base', '--app', root, '--format', 'json')
      missed = JSON.parse(json)['frames'].last
      assert_equal [false, nil, -0.00025], missed.values_at('schedulable', 'response_time', 'slack')
    end

    # A jitter of 100,000 s on a 1 ms frame (a typo for 100 us) used to
    # keep the analysis going for minutes; it is now one instance.
    def test_a_jitter_past_the_deadline
      root = my_app(<<~RUBY)
        com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(500_000)
        through 'can0' do
          device(Devices::TemperatureSensor, as: 'a').can_id(1).frame(1, bytes: 8, period: 0.001, jitter: 100_000)
        end
      RUBY
      out, _, status = timing('Base', '--app', root)
      assert_equal 1, status
      assert_match(/^001 +a +8 +1.000 +1.000 +100000000.000 +0.270 +0.000 +100000000.270 +-99999999.270 +MISS$/, out)
      out, _, status = run_cli('check', '--app', root)
      assert_equal 1, status
      assert_includes out, "models/profiles/base.rb:11: frame 0x001 of a on bus 'can0' can miss its deadline: " \
                           "worst-case response time 100000000.27 ms, deadline 1 ms\n  hint: its jitter alone " \
                           '(100000000 ms, plus its own transmission) is past its deadline'
    end

    # The analysis of a frame stops at its first late instance: a later
    # one could take longer, so its times are bounds.
    def test_a_miss_found_before_the_latest_instance
      root = my_app(PAPER.sub('deadline: 0.00325', 'jitter: 0.00075'))
      out, _, status = timing('Base', '--app', root)
      assert_equal 1, status
      assert_equal %w[003 c 8 3.500 3.500 0.750 1.000 0.000 >=3.750 <=-0.250 MISS], out.lines[6].split
      assert_match(/^>= a response time past the deadline is that of the frame's first late instance/, out)
      out, = run_cli('check', '--app', root)
      assert_match(/frame 0x003 of c on bus 'can0' can miss its deadline: worst-case response time at least 3.75 ms/,
                   out)
    end

    # As plan and replay: a robot that does not exist is refused, not
    # ignored (the traffic is the profile's, whatever the robot).
    def test_an_unknown_robot_is_refused
      out, err, status = timing('Live::Base', '--bus', 'can1', '--robot', 'nosuch', '--app', EXAMPLE)
      assert_equal [1, ''], [status, out]
      assert_equal "config/robots/nosuch.rb: no configuration for robot 'nosuch'\n  hint: create " \
                   "config/robots/nosuch.rb with Syskit.conf.use_deployment statements\n", err
    end

    def test_an_overloaded_bus
      root = my_app(<<~RUBY)
        com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(135_000)
        through 'can0' do
          device(Devices::TemperatureSensor, as: 'a').can_id(1).frame(1, bytes: 8, period: 0.001)
        end
      RUBY
      out, _, status = timing('Base', '--app', root)
      assert_equal 1, status
      assert_match(/^001 +a +8 +1.000 +1.000 +0.000 +1.000 +0.000 +- +- +MISS \(unbounded\)$/, out)
      assert_match(/^the bus is loaded 100.0 %: it cannot carry this traffic$/, out)
    end

    def test_which_bus
      _, err, status = timing('Live::Base', '--app', EXAMPLE)
      assert_equal [1, "AwesomeRobot::Profiles::Live::Base has several CAN buses\n  " \
                       "hint: choose one with --bus (can0, can1)\n"], [status, err]
      _, err, = timing('Live::Base', '--bus', 'n2k', '--app', EXAMPLE)
      assert_equal "bus 'n2k' is attached to bus 'can0': its frames travel on can0's wire\n  " \
                   "hint: time that bus: --bus can0\n", err
      _, err, = timing('Live::Base', '--bus', 'gps', '--app', EXAMPLE)
      assert_match(/\Adevice 'gps' is not a CAN bus\n  hint: choose one with --bus \(can0, can1\)/, err)
    end

    def test_a_bus_without_bitrate
      root = my_app(<<~RUBY)
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through('can0') { device(Devices::TemperatureSensor, as: 'a').can_id(1).frame(1, bytes: 8, period: 0.01) }
      RUBY
      _, err, status = timing('Base', '--app', root)
      assert_equal 1, status
      assert_equal "models/profiles/base.rb:9: bus 'can0' has no bitrate: its frames cannot be timed\n  " \
                   "hint: declare it: com_bus(..., as: 'can0').bitrate(500_000)\n", err
    end
  end
end
