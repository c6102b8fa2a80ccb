# frozen_string_literal: true

require_relative 'lsp_helper'

module Syskit
  # Document symbols: the outline of a file, from what the app recorded.
  class TestLSPDocumentSymbols < Minitest::Test
    include SelfTest::LSPHelper

    def query
      @query ||= LSP::DocumentSymbols.new(example_app)
    end

    def symbols(relative, text = nil)
      path = example(relative)
      query.of(path, text || File.read(path))
    end

    # name => [kind, first line, last line] of +symbols+.
    def outline(symbols)
      symbols.to_h { |s| [s[:name], [s[:kind], s[:range][:start][:line], s[:range][:end][:line]]] }
    end

    def test_a_profile_with_its_devices_and_definitions
      path = example('models/profiles/live/base.rb')
      profile, *others = symbols('models/profiles/live/base.rb')
      assert_empty others
      assert_equal ['AwesomeRobot::Profiles::Live::Base', 2, 'profile'], profile.values_at(:name, :kind, :detail)
      children = outline(profile[:children])
      assert_equal %w[gps forward_camera aft_camera can0 temperature_sensor water_temperature sync n2k fuel_level
                      can1 left_motor right_motor drive_def watch_temperatures_def], children.keys
      gps = line_of(path, "as: 'gps'") - 1
      assert_equal [13, gps, gps], children['gps']
      assert_equal 12, children['drive_def'][0]
      # The profile spans its children.
      assert_equal line_of(path, "profile 'Base'") - 1, profile[:range][:start][:line]
      assert_equal children['watch_temperatures_def'][2], profile[:range][:end][:line]
    end

    def test_a_profile_s_buses_are_told_from_its_devices
      details = symbols('models/profiles/live/base.rb').first[:children].to_h { |c| [c[:name], c[:detail]] }
      assert_equal %w[bus device], details.values_at('can0', 'gps')
    end

    def test_a_composition_spans_its_class_body_and_has_its_children
      path = example('models/compositions/drive.rb')
      drive = symbols('models/compositions/drive.rb').first
      first = line_of(path, 'class Drive') - 1
      assert_equal [5, first, line_of(path, 'export follower_child')], outline([drive])[drive[:name]]
      assert_equal({ start: { line: first, character: 4 }, end: { line: first, character: 37 } },
                   drive[:selectionRange])
      assert_equal(%w[position follower left right], drive[:children].map { |c| c[:name] })
    end

    def test_models_and_task_models
      assert_equal({ 'AwesomeRobot::Devices::GPS::Ublox::F9' => [5, 7, 7] },
                   outline(symbols('models/devices/gps/ublox/f9.rb')))
      assert_equal({ 'AwesomeRobot::Services::Position' => [11, 3, 3] },
                   outline(symbols('models/services/position.rb')))
      assert_equal(%w[navigation::PathFollower navigation::TemperatureMonitor],
                   symbols('models/orogen/navigation.orogen').map { |s| s[:name] })
    end

    def test_lines_the_buffer_no_longer_has_are_left_out
      assert_empty symbols('models/devices/gps/ublox/f9.rb', "# emptied\n")
      assert_empty symbols('models/devices/gps/ublox/f9.rb', '')
    end

    def test_a_file_that_declares_nothing_or_is_not_of_the_app
      assert_empty symbols('config/robots/default.rb')
      assert_empty query.of('/nowhere/x.rb', "module X\nend\n")
    end

    def test_a_file_that_failed_to_load_has_what_was_declared_before_its_error
      app, path = app_with_broken_profile
      profile, = LSP::DocumentSymbols.new(app).of(path, File.read(path))
      assert_equal 'MyApp::Profiles::Base', profile[:name]
      assert_equal(['imu'], profile[:children].map { |c| c[:name] })
    end
  end
end
