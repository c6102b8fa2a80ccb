# frozen_string_literal: true

require 'helper'

module Syskit
  # Values as Rock's configuration files write them beyond plain YAML:
  # Ruby between <%= and %>, numbers with units and with a rounding.
  class TestConfValues < Minitest::Test
    CONF = 'config/orogen/imu::Task.yml'
    FILES = {
      'models/typekits/imu.rb' => <<~RUBY,
        struct 'Window' do
          field 'low', '/double'
          field 'high', '/double'
          field 'samples', '/uint32_t'
        end
      RUBY
      'models/orogen/imu.orogen' => <<~RUBY
        name 'imu'
        import_types_from 'base'
        import_types_from 'imu'
        task_context 'Task' do
          property 'device', '/std/string', '/dev/ttyUSB0'
          property 'rate', 'int', 100
          property 'tilt', '/double'
          property 'window', '/imu/Window'
          property 'steps', '/std/vector</double>'
          property 'label', '/std/string'
          output_port 'samples', '/base/samples/IMUSensors'
        end
      RUBY
    }.freeze

    # The properties of the imu task planned with the section 'test' of +conf+.
    def planned(conf)
      app = load_app(my_app("device(Devices::IMU, as: 'imu').with_conf('test')\n", FILES.merge(CONF => conf)))
      properties = Network::Generator.plan_profile(app, MyApp::Profiles::Base.syskit_profile).plan
                                     .find_task('imu').properties
      [properties, app.problems, app.root]
    ensure
      @loaded_apps&.pop&.unload
    end

    def checked(conf)
      root = my_app("device(Devices::IMU, as: 'imu')\n", FILES.merge(CONF => conf))
      [load_app(root, problems: true, everything: true).problems, root]
    ensure
      @loaded_apps&.pop&.unload
    end

    def test_embedded_ruby_is_replaced_by_its_value_before_the_yaml_is_read
      ENV['SYSKIT_TEST_DATA_ROOT'] = '/srv/robot'
      properties, = planned(<<~YAML)
        --- name:test
        device: "<%= ENV['SYSKIT_TEST_DATA_ROOT'] %>/dev/imu<%= 1 + 1 %>"
        rate: <%= 25 * 4 %>
        label: "<%= nil %>none"
      YAML
      assert_equal ['/srv/robot/dev/imu2', 200 / 2, 'none'], properties.values_at('device', 'rate', 'label')
    ensure
      ENV.delete('SYSKIT_TEST_DATA_ROOT')
    end

    def test_embedded_ruby_that_fails_is_reported_at_its_line
      problems, root = checked("--- name:default\nrate: 10\n--- name:other\ndevice: \"<%= data_root %>/imu\"\n")
      assert_reported problems.first, /in the Ruby of <%= data_root %>: .*undefined local variable or method/,
                      at: "#{CONF}:4", root: root
    end

    def test_numbers_with_units_are_converted_to_si_where_a_number_goes
      properties, problems = planned(<<~YAML)
        --- name:test
        tilt: 90.deg
        rate: 2.5.round
        window: { low: 150.ms, high: 1.5.km, samples: 3.5.ceil }
        steps: [1, 2.cm^2, -3.mus]
        label: 2.deg
      YAML
      assert_in_delta Math::PI / 2, properties['tilt']
      assert_equal 3, properties['rate']
      window = properties['window']
      assert_in_delta 0.15, window['low']
      assert_in_delta 1500.0, window['high']
      assert_equal 4, window['samples']
      assert_equal 3, properties['steps'].size
      assert_in_delta 2e-4, properties['steps'][1]
      assert_in_delta(-3e-6, properties['steps'][2])
      # A string keeps its text: only numeric fields read units.
      assert_equal '2.deg', properties['label']
      assert_empty problems.grep(Warning)
    end

    def test_a_fraction_for_an_integer_field_is_rounded_down_with_a_warning
      properties, problems, root = planned("--- name:test\nrate: 12.7\n")
      assert_equal 12, properties['rate']
      warnings = problems.grep(Warning)
      assert_equal 1, warnings.size
      assert_reported warnings.first, /rate: 12.7 given to an integer field is rounded down to 12/,
                      at: "#{CONF}:2", hint: /\.round, \.floor or \.ceil/, root: root
      # A whole number is exact: no warning.
      properties, problems, = planned("--- name:test\nrate: 3.0\n")
      assert_equal 3, properties['rate']
      assert_empty problems.grep(Warning)
    end

    def test_a_number_that_cannot_be_read_is_reported_at_its_line
      problems, root = checked("--- name:default\ntilt: 3.furlong\n--- name:b\nrate: 12 Hz\n")
      assert_equal 2, problems.size, problems.map { |p| p.report(root) }.join("\n")
      assert_reported problems[0], /property 'tilt' of imu::Task: "3.furlong": 'furlong' is not a unit/,
                      at: "#{CONF}:2", hint: /2\.deg, 150\.ms/, root: root
      assert_reported problems[1], /property 'rate' of imu::Task: "12 Hz" is not a number followed by units/,
                      at: "#{CONF}:4", root: root
    end
  end
end
