# frozen_string_literal: true

require 'helper'

module Syskit
  module Checks
    # `syskit check` reads every section of every configuration file against
    # its task model, as Rock does when it loads the file: the sections no
    # profile asks for too.
    class TestConfSections < Minitest::Test
      def check(conf)
        root = my_app("device(Devices::IMU, as: 'imu')\n", 'config/orogen/imu::Task.yml' => conf)
        run_cli('check', '--app', root)
      end

      def test_every_section_is_checked_whether_used_or_not
        out, _, status = check(<<~YAML)
          --- name:default
          rate: 50
          --- name:bench
          rte: 10
          device: /dev/ttyS0
          --- name:outdoor
          rate: fast
        YAML
        assert_equal 1, status
        assert_equal [
          "config/orogen/imu::Task.yml:4: imu::Task has no property 'rte' (did you mean 'rate'?) (section 'bench' " \
          'of imu::Task.yml)',
          '  hint: its properties are device, rate',
          "config/orogen/imu::Task.yml:7: property 'rate' of imu::Task: expected an integer for /int32_t, " \
          'got "fast"',
          '  hint: give it a value of type /int32_t',
          'MyApp: 2 error(s), 0 warning(s)'
        ], out.lines.map(&:chomp)
      end

      # A section a profile uses is reported once, not again by the plan.
      def test_a_used_section_is_reported_once
        out, _, status = check("--- name:default\nrat: 50\n")
        assert_equal 1, status
        assert_equal 1, out.scan("has no property 'rat'").size, out
      end

      # Past the first SHOWN unknown properties of a file, one line says
      # how many more there are, at the line of the first of them: the
      # report stays readable, and the check linear (rake bench measures
      # its growth).
      def test_many_unknown_properties_are_counted_past_the_first
        keys = 8.times.map { |i| "a#{i}: 1\n" }.join
        more = 7.times.map { |i| "b#{i}: 1\n" }.join
        out, _, status = check("--- name:default\n#{keys}rate: 5\n--- name:spare\n#{more}")
        assert_equal 1, status
        assert_equal 10, out.scan('has no property').size, out
        assert_includes out, "imu::Task.yml:13: imu::Task has no property 'b1' (section 'spare' of imu::Task.yml)\n"
        assert_includes out, 'config/orogen/imu::Task.yml:14: 5 more properties that imu::Task does not have in ' \
                             "imu::Task.yml ('b2', 'b3', 'b4', ...; the first 10 are listed one by one)\n  " \
                             "hint: its properties are device, rate\n"
        assert_match(/^MyApp: 11 error\(s\)/, out)
      end

      def test_a_file_whose_sections_all_fit_passes
        out, _, status = check("--- name:default\nrate: 50\n--- name:spare\ndevice: /dev/ttyS1\n")
        assert_equal 0, status, out
      end
    end
  end
end
