# frozen_string_literal: true

require 'helper'
require 'json'
require 'syskit/bus/candump_log'

module Syskit
  # `syskit bus replay`, through the command line.
  class TestBusReplay < Minitest::Test
    # A bus with every case the report distinguishes: two standard filters
    # that overlap (wide contains narrow), an extended filter on the same
    # number as a standard one, a PGN-style extended filter, a device with
    # no filter and a write-only device. The bus driver does not
    # demultiplex, so a device may have no filter.
    APP = {
      'config/syskit.yml' => "name: MyApp\n",
      'models/devices/probe.rb' => "module MyApp\n  module Devices\n    device_type 'Probe'\n  end\nend\n",
      'models/orogen/probe.orogen' => <<~RUBY,
        name 'probe'
        import_types_from 'canbus'
        task_context 'Task' do
          input_port('can_in', '/canbus/Message').needs_reliable_connection
          output_port 'can_out', '/canbus/Message'
        end
      RUBY
      'models/orogen/probe.rb' => <<~RUBY,
        require 'models/devices/probe'
        Syskit.extend_model OroGen.probe.Task do
          driver_for MyApp::Devices::Probe, as: 'probe'
        end
      RUBY
      'models/orogen/plain_can.orogen' => <<~RUBY,
        name 'plain_can'
        import_types_from 'canbus'
        task_context 'Task' do
          input_port('can_in', '/canbus/Message').multiplexes.needs_reliable_connection
          output_port 'can_out', '/canbus/Message'
        end
      RUBY
      'models/orogen/plain_can.rb' => <<~RUBY,
        Syskit.extend_model OroGen.plain_can.Task do
          provides CommonModels::Devices::Bus::CAN::BusSrv, as: 'canbus'
        end
      RUBY
      'models/profiles/base.rb' => <<~RUBY,
        using_task_library 'probe'
        using_task_library 'plain_can'

        module MyApp
          module Profiles
            profile 'Base' do
              robot do
                com_bus CommonModels::Devices::Bus::CAN, as: 'can0', using: OroGen.plain_can.Task
                through 'can0' do
                  device(Devices::Probe, as: 'wide').can_id(0x100, 0x700).prefer_deployed_tasks('wide')
                  device(Devices::Probe, as: 'narrow').can_id(0x120, 0x7F0).prefer_deployed_tasks('narrow')
                  device(Devices::Probe, as: 'exact_ext').can_id(0x120, 0x1FFFFFFF).prefer_deployed_tasks('exact_ext')
                  device(Devices::Probe, as: 'pgn').can_id(0x18FEF100, 0x1FFFFF00).prefer_deployed_tasks('pgn')
                  device(Devices::Probe, as: 'mute').prefer_deployed_tasks('mute')
                  device(Devices::Probe, as: 'writer', bus_to_client: false).can_id(0x200, 0x7FF)
                    .prefer_deployed_tasks('writer')
                end
              end
            end
          end
        end
      RUBY
      'config/robots/default.rb' => <<~RUBY
        Syskit.conf.use_deployment OroGen.plain_can.Task => 'can0'
        %w[wide narrow exact_ext pgn mute writer].each do |name|
          Syskit.conf.use_deployment OroGen.probe.Task => name
        end
      RUBY
    }.freeze

    # 0.1 s apart: 125 (wide+narrow) x3, 1FF (wide) x2, 00000120 (exact_ext)
    # x2, 18FEF1AB (pgn) x2 of which one CAN FD, 120 RTR (wide+narrow), 7E5
    # (nobody) x2, 0000ABCD (nobody), an error frame, two malformed lines.
    LOG = <<~LOG
      (1600000000.000000) can0 125#0102
      (1600000000.100000) can0 1FF#
      (1600000000.200000) can0 00000120#AA
      (1600000000.300000) can0 18FEF1AB#0011223344556677
      (1600000000.400000) can0 125#03
      (1600000000.500000) can0 7E5#00
      this is not a frame
      (1600000000.600000) can0 120#R
      (1600000000.700000) can0 18FEF1AB##1000102030405060708090A0B
      (1600000000.800000) can0 0000ABCD#01
      (1600000000.900000) can0 20000004#0000080000000000
      (1600000001.000000) can0 125#04
      (1600000001.100000) can0 1FF#FF
      (1600000001.200000) can0 00000120#BB
      (1600000001.300000) can0 123#123
      (1600000001.400000) can0 7E5#00
    LOG

    def setup
      super
      @app = write_app(APP)
      @log = File.join(@app, 'can0.log')
      File.write(@log, LOG)
    end

    def replay_json(*args, log: @log)
      out, err, status = run_cli('bus', 'replay', 'Base', log, '--app', @app, '--bus', 'can0', '--format', 'json',
                                 *args)
      assert_equal 0, status, err
      JSON.parse(out)
    end

    def device(report, name)
      report['devices'].find { |d| d['name'] == name } || flunk("no device #{name}")
    end

    def test_counts_what_each_device_receives_by_its_filter
      report = replay_json
      counts = report['devices'].to_h { |d| [d['name'], [d['frames'], d['ids']]] }
      assert_equal({ 'exact_ext' => [2, ['00000120']], 'mute' => [0, []], 'narrow' => [4, %w[120 125]],
                     'pgn' => [2, ['18FEF1AB']], 'wide' => [6, %w[120 125 1FF]], 'writer' => [0, []] }, counts)
    end

    def test_reports_first_and_last_time_and_mean_rate
      wide = device(replay_json, 'wide')
      assert_in_delta 1_600_000_000.0, wide['first_time'], 1e-6
      assert_in_delta 1_600_000_001.1, wide['last_time'], 1e-6
      # 6 frames in the 1.4 s of the log.
      assert_in_delta 6 / 1.4, wide['rate'], 1e-3
      assert_in_delta 0.0, device(replay_json, 'mute')['rate']
      assert_nil device(replay_json, 'writer')['rate']
    end

    def test_standard_and_extended_frames_with_the_same_number_stay_apart
      report = replay_json
      assert_equal ['00000120'], device(report, 'exact_ext')['ids']
      refute_includes device(report, 'wide')['ids'], '00000120'
      assert device(report, 'exact_ext')['filter']['extended']
      refute device(report, 'narrow')['filter']['extended']
    end

    def test_devices_that_receive_nothing_say_why
      report = replay_json
      assert_equal 'no_filter', device(report, 'mute')['status']
      assert_equal 'write_only', device(report, 'writer')['status']
      assert_equal 'filtered', device(report, 'wide')['status']
    end

    def test_frames_no_device_receives_are_grouped_by_id
      unclaimed = replay_json['unclaimed'].map { |u| [u['hex'], u['extended'], u['frames']] }
      assert_equal [['7E5', false, 2], ['0000ABCD', true, 1]], unclaimed
    end

    def test_unclaimed_ids_name_the_write_only_devices_whose_filter_matches
      File.write(@log, "(1.000000) can0 200#01\n(2.000000) can0 200#02\n(3.000000) can0 7E5#00\n")
      unclaimed = replay_json['unclaimed'].map { |u| [u['hex'], u['write_only_matches']] }
      assert_equal [['200', ['writer']], ['7E5', []]], unclaimed
      out, = run_cli('bus', 'replay', 'Base', @log, '--app', @app)
      assert_match(/^  200 +2 +0\.000 +1\.000  filter of write-only writer$/, out)
    end

    # A device whose declared frame stops before the log ends: the gaps
    # between its frames are fine, the report says it fell silent.
    def test_a_declared_frame_that_stops_before_the_end_of_the_log
      profile = File.join(@app, 'models', 'profiles', 'base.rb')
      File.write(profile, File.read(profile).sub('can_id(0x100, 0x700)',
                                                 'can_id(0x100, 0x700).frame(0x150, bytes: 1, period: 0.1)'))
      File.write(@log, "(1.000000) can0 150#01\n(1.100000) can0 150#01\n(1.200000) can0 150#01\n" \
                       "(2.000000) can0 7E5#00\n")
      out, err, status = run_cli('bus', 'replay', 'Base', @log, '--app', @app)
      assert_equal 0, status, err
      assert_match(/^  150 +wide +100\.000 +3 +100\.000 +100\.000  silent for the last 800\.000 ms of the log$/, out)
    end

    # Without PROFILE, as plan and bus timing: the app's first profile.
    def test_replay_without_a_profile_replays_the_first_one
      File.write(@log, "(1.000000) can0 200#01\n")
      with_profile, = run_cli('bus', 'replay', 'Base', @log, '--app', @app)
      out, err, status = run_cli('bus', 'replay', @log, '--app', @app)
      assert_equal [0, with_profile], [status, out], err
    end

    # A frame a device declares and no filter receives: the host sends it
    # to the device (a command); the report says who declared it.
    def test_unclaimed_ids_name_the_devices_that_declare_them
      profile = File.join(@app, 'models', 'profiles', 'base.rb')
      File.write(profile, File.read(profile).sub('can_id(0x100, 0x700)',
                                                 'can_id(0x100, 0x700).frame(0x7E5, bytes: 1, period: 0.1)'))
      unclaimed = replay_json['unclaimed'].map { |u| [u['hex'], u['declared_by']] }
      assert_equal [['7E5', ['wide']], ['0000ABCD', []]], unclaimed
      out, = run_cli('bus', 'replay', 'Base', @log, '--app', @app)
      assert_match(/^  7E5 +2 +0\.500 +1\.400  declared by wide: host to device$/, out)
      assert_match(/^  0000ABCD +1 +0\.800 +0\.800$/, out)
    end

    def test_frames_several_devices_receive_are_grouped_by_id_with_the_devices
      overlaps = replay_json['overlaps'].map { |o| [o['hex'], o['frames'], o['devices']] }
      assert_equal [['120', 1, %w[narrow wide]], ['125', 3, %w[narrow wide]]], overlaps
    end

    def test_counts_frame_kinds_and_skips_error_frames
      report = replay_json
      assert_equal({ 'total' => 14, 'standard' => 8, 'extended' => 5, 'fd' => 1, 'rtr' => 1, 'error' => 1 },
                   report['frames'])
      assert_in_delta 1.4, report['duration'], 1e-6
    end

    def test_malformed_lines_are_counted_with_their_line_numbers
      malformed = replay_json['source']['malformed']
      assert_equal 2, malformed['count']
      assert_equal([7, 15], malformed['lines'].map { |l| l['line'] })
      assert_match(/odd|pairs of hex digits/, malformed['lines'][1]['message'])
      assert_equal '(1600000001.300000) can0 123#123', malformed['lines'][1]['text']
    end

    def test_keeps_only_the_first_few_malformed_lines
      File.write(@log, "#{LOG}#{"junk\n" * 20}")
      malformed = replay_json['source']['malformed']
      assert_equal 22, malformed['count']
      assert_equal Bus::CandumpLog::KEEP_MALFORMED, malformed['lines'].size
    end

    def test_strict_makes_a_malformed_line_an_error_at_its_line
      out, err, status = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--bus', 'can0', '--strict')
      assert_equal 1, status
      assert_equal '', out
      lines = err.lines
      # The log is in the app: its path is shown relative to the app's root.
      assert_equal "can0.log:7: malformed candump line: expected '(seconds.microseconds) interface frame', " \
                   "as candump -l writes (and 1 more malformed line)\n", lines[0]
      assert_match(/\A  hint: lines look like/, lines[1])
      assert_equal 2, lines.size, 'no backtrace'
    end

    def test_strict_accepts_a_clean_log
      File.write(@log, LOG.lines.values_at(0, 1, 2).join)
      _, err, status = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--bus', 'can0', '--strict')
      assert_equal 0, status, err
    end

    def test_the_text_report
      out, err, status = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--bus', 'can0')
      assert_equal 0, status, err
      assert_includes out, "Bus can0 of MyApp::Profiles::Base (robot default)\n"
      assert_includes out, "interface can0: 14 frames in 1.400 s\n"
      assert_includes out, "  standard 8, extended 5, CAN FD 1, RTR 1, error frames 1\n"
      assert_match(%r{^wide +100/700 +6 +3 +0\.000 +1\.100 +4\.3$}, out)
      assert_match(%r{^exact_ext +00000120/1FFFFFFF ext +2 +1 +0\.200 +1\.200 +1\.4$}, out)
      assert_match(/^mute +no can_id filter: receives nothing by filter$/, out)
      assert_match(/^writer +write-only \(bus_to_client: false\): receives nothing$/, out)
      assert_includes out, "Frames no device receives: 2 ids, 3 frames\n"
      assert_match(/^  0000ABCD +1 +0\.800 +0\.800$/, out)
      assert_includes out, "Frames several devices receive: 2 ids, 4 frames\n"
      assert_match(/^  125 +3 +0\.000 +1\.000  narrow, wide$/, out)
      assert_includes out, "Malformed lines: 2\n  #{@log}:7: expected"
    end

    def test_reads_the_first_interface_of_a_log_unless_told
      File.write(@log, "(1.000000) can1 7E5#00\n(2.000000) can0 125#00\n(3.000000) can1 7E5#00\n")
      report = replay_json
      assert_equal 'can1', report['source']['interface']
      assert_equal({ 'can0' => 1 }, report['source']['other_interfaces'])
      assert_equal 2, report['frames']['total']

      report = replay_json('--interface', 'can0')
      assert_equal 1, report['frames']['total']
      assert_equal({ 'can1' => 2 }, report['source']['other_interfaces'])
    end

    # A log's bytes are not always UTF-8 (a Latin-1 interface name, a
    # damaged line): JSON and the text report write them \xNN.
    def test_bytes_that_are_not_utf8_are_written_as_escapes
      File.binwrite(@log, "(1.000000) can\xE9 125#00\n(2.000000) can0 125#00\n(3.0\xFF) can0 125#00\n".b)
      source = replay_json['source']
      assert_equal ['can\\xE9', { 'can0' => 1 }], source.values_at('interface', 'other_interfaces')
      assert_equal '(3.0\\xFF) can0 125#00', source['malformed']['lines'].first['text']
      out, = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--bus', 'can0')
      assert_match(/^log .*, interface can\\xE9: 1 frame in 0.000 s$/, out)
      assert out.valid_encoding?
      _, err, status = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--interface', "can\xE9".b)
      assert_equal [1, "the argument 'can\\xE9' is not UTF-8 text\n  hint: arguments are names and paths written " \
                       "in UTF-8; rename a file whose name is not\n"], [status, err]
    end

    # Two logs merged into one: gaps and periods between lines in log
    # order are not the frames' (the longest gap was 0, nothing late).
    def test_a_log_not_in_time_order_says_where
      File.write(@log, "(10.000000) can0 125#00\n(10.100000) can0 125#00\n(9.950000) can0 125#00\n" \
                       "(10.050000) can0 125#00\n(9.990000) can0 125#00\n")
      assert_equal({ 'line' => 3, 'time' => 9.95, 'previous_time' => 10.1, 'lines' => 2 },
                   replay_json['source']['backwards'])
      out, = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--bus', 'can0')
      assert_includes out, "\n  not in time order: line 3 is 0.150 s before the line before it (2 lines back in " \
                           "time): gaps, periods and late frames are measured in log order, sort the log by time\n"
      _, err, status = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--bus', 'can0', '--strict')
      assert_equal [1, 'can0.log:3: the log is not in time order: this line is 0.150 s before the line before it ' \
                       "(2 lines back in time)\n"], [status, err.lines.first]
      assert_nil replay_json(log: write_ordered_log)['source']['backwards']
    end

    def write_ordered_log
      File.join(@app, 'ordered.log').tap { |path| File.write(path, "(1.000000) can0 125#00\n(1.000000) can0 125#00\n") }
    end

    def test_without_bus_uses_the_only_bus_of_the_plan
      out, err, status = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--format', 'json')
      assert_equal 0, status, err
      assert_equal 'can0', JSON.parse(out)['bus']
    end

    def test_an_unknown_bus_is_an_error_listing_the_buses
      _, err, status = run_cli('bus', 'replay', 'Base', @log, '--app', @app, '--bus', 'can9')
      assert_equal 1, status
      assert_equal "the plan has no bus named 'can9' (did you mean 'can0'?)\n  hint: buses with devices: can0\n", err
    end

    def test_a_missing_log_is_an_error
      _, err, status = run_cli('bus', 'replay', 'Base', '/nonexistent/can0.log', '--app', @app)
      assert_equal 1, status
      assert_match %r{\Acannot read /nonexistent/can0.log: No such file or directory}, err
      assert_match(/  hint: /, err)
    end

    def test_trace_adds_the_backtrace
      _, err, status = run_cli('bus', 'replay', 'Base', '/nonexistent/can0.log', '--app', @app, '--trace')
      assert_equal 1, status
      assert_match %r{^    .*lib/syskit/bus/replay\.rb:\d+}, err
    end

    def test_an_unknown_profile_is_an_error
      _, err, status = run_cli('bus', 'replay', 'Nope', @log, '--app', @app)
      assert_equal 1, status
      assert_match(/\Ano profile named 'Nope'/, err)
    end

    def test_the_example_app_log
      out, err, status = run_cli('bus', 'replay', 'Live::Base', 'examples/awesome_robot/logs/can0.log',
                                 '--app', 'examples/awesome_robot', '--bus', 'can0', '--format', 'json')
      assert_equal 0, status, err
      report = JSON.parse(out)
      receiving = report['devices'].select { |d| d['status'] == 'filtered' }
      assert_equal(%w[n2k temperature_sensor water_temperature], receiving.map { |d| d['name'] })
      assert(receiving.all? { |d| d['frames'].positive? })
      assert_equal 'write_only', device(report, 'sync')['status']
    end
  end
end
