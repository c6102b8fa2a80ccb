# frozen_string_literal: true

require 'helper'
require 'syskit/check'

module Syskit
  module Checks
    # `syskit check`'s CAN timing problems, located where the user acts.
    class TestCanTiming < Minitest::Test
      # The robot block's first line in models/profiles/base.rb.
      FIRST = 9

      def timing_problems(robot)
        @app = App.new(my_app(robot))
        (@loaded_apps ||= []) << @app
        problems = Check.new(@app).run.problems
        problems.select { |p| p.is_a?(TimingError) || p.message.match?(/loaded|bitrate/) }
      end

      def at(line)
        "models/profiles/base.rb:#{FIRST + line}"
      end

      def reported(problem)
        [problem.class, problem.location.to_s(@app.root)]
      end

      # Davis et al.'s example: 1 ms frames (8 bytes at 135 kbit/s).
      PAPER = <<~RUBY
        com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(135_000)
        through 'can0' do
          device(Devices::TemperatureSensor, as: 'a').frame(1, bytes: 8, period: 0.0025)
          device(Devices::TemperatureSensor, as: 'b').frame(2, bytes: 8, period: 0.0035)
          device(Devices::TemperatureSensor, as: 'c').frame(3, bytes: 8, period: 0.0035, deadline: 0.00325)
        end
      RUBY

      def test_a_frame_that_can_miss_its_deadline_is_an_error_at_its_declaration
        miss, load = timing_problems(PAPER)
        assert_equal [TimingError, at(4)], reported(miss)
        assert_equal "frame 0x003 of c on bus 'can0' can miss its deadline: worst-case response time 3.5 ms, " \
                     'deadline 3.25 ms', miss.message
        assert_match(/syskit bus timing MyApp::Profiles::Base --bus can0 shows every frame/, miss.hint)
        assert_equal [Warning, at(0)], reported(load)
        assert_equal "bus 'can0' is loaded 97.1 %, above its warning level of 70.0 %", load.message
        assert_match(/bitrate\(135000, warn_above: 0.8\)/, load.hint)
      end

      def test_an_overloaded_bus
        problems = timing_problems(<<~RUBY)
          com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(135_000)
          through 'can0' do
            device(Devices::TemperatureSensor, as: 'a').frame(1, bytes: 8, period: 0.002)
            device(Devices::TemperatureSensor, as: 'b').frame(2, bytes: 8, period: 0.002)
              .frame(3, bytes: 8, period: 0.1)
          end
        RUBY
        assert_equal 1, problems.size, problems.map(&:message).inspect
        assert_equal [TimingError, at(0)], reported(problems.first)
        assert_match(%r{bus 'can0' is loaded 101.0 % at 135 kbit/s: 2 of its frames \(from 0x002 down\) have no},
                     problems.first.message)
        assert_match(/raise the bitrate/, problems.first.hint)
      end

      def test_one_identifier_declared_by_two_devices
        problems = timing_problems(<<~RUBY)
          com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(500_000)
          through 'can0' do
            device(Devices::TemperatureSensor, as: 'left').frame(0x181, bytes: 8, period: 0.01)
            device(Devices::TemperatureSensor, as: 'right').frame(0x181, bytes: 8, period: 0.01)
            device(Devices::TemperatureSensor, as: 'ext').frame(0x181, bytes: 8, period: 0.01, extended: true)
          end
        RUBY
        assert_equal 1, problems.size, problems.map(&:message).inspect
        assert_equal [TimingError, at(3)], reported(problems.first)
        assert_match(/frame 0x181 is declared by left and right on bus 'can0': two senders of one identifier break CAN arbitration \(the first is declared at .*base.rb:#{FIRST + 2}\)/, # rubocop:disable Layout/LineLength
                     problems.first.message)
      end

      def test_frames_without_a_bitrate_are_a_warning_naming_bitrate
        problems = timing_problems(<<~RUBY)
          com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
          through 'can0' do
            device(Devices::TemperatureSensor, as: 't').frame(0x181, bytes: 8, period: 0.01)
          end
        RUBY
        assert_equal([[Warning, at(0)]], problems.map { |p| reported(p) })
        assert_equal "bus 'can0' carries 1 declared frame but has no bitrate: their timing is not checked",
                     problems.first.message
        assert_match(/com_bus\(\.\.\., as: 'can0'\)\.bitrate\(500_000\)/, problems.first.hint)
      end

      def test_the_warning_level_is_the_buses
        robot = lambda do |level|
          <<~RUBY
            com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(135_000, warn_above: #{level})
            through('can0') { device(Devices::TemperatureSensor, as: 't').frame(1, bytes: 8, period: 0.002) }
          RUBY
        end
        assert_match(/loaded 50.0 %, above its warning level of 40.0 %/, timing_problems(robot[0.4]).first.message)
        @loaded_apps.pop.unload
        assert_empty timing_problems(robot[0.6])
      end

      def test_a_bus_that_carries_its_traffic_in_time_has_no_problem
        assert_empty timing_problems(<<~RUBY)
          com_bus(CommonModels::Devices::Bus::CAN, as: 'can0').bitrate(500_000)
          through 'can0' do
            device(Devices::TemperatureSensor, as: 't').frame(0x181, bytes: 8, period: 0.01)
          end
          com_bus CommonModels::Devices::Bus::CAN, as: 'can1'
        RUBY
      end
    end
  end
end
