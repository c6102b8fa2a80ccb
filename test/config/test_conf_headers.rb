# frozen_string_literal: true

require 'helper'
require 'pathname'

module Syskit
  # Rock's section header options in configuration files, applied as
  # Rock's loader applies them: --- name:x merge:true chain:a,b. Anything
  # else on a header line is refused, at its line.
  class TestConfHeaders < Minitest::Test
    CONF = 'config/orogen/imu::Task.yml'
    # imu::Task's properties before any section applies.
    DEFAULTS = { 'device' => '/dev/ttyUSB0', 'rate' => 100 }.freeze

    # The properties of the imu task planned with the sections +sections+;
    # +bundle_conf+ is the same task's file in a bundle the app uses.
    def properties(conf, sections, bundle_conf: nil)
      files = { CONF => conf }
      if bundle_conf
        bundle = write_app({ CONF => bundle_conf, 'config/syskit.yml' => "name: Parts\n" }, name: 'parts')
        files['config/syskit.yml'] = "name: MyApp\nacronyms: [IMU, CAN]\nbundles: [#{bundle}]\n"
      end
      root = my_app("device(Devices::IMU, as: 'imu').with_conf(#{sections.map(&:inspect).join(', ')})\n", files)
      app = load_app(root)
      properties = Network::Generator.plan_profile(app, MyApp::Profiles::Base.syskit_profile).plan
                                     .find_task('imu').properties
      # What the sections set, the defaults left out.
      properties.reject { |name, value| DEFAULTS[name] == value }
    ensure
      @loaded_apps&.pop&.unload
    end

    def conf_error(conf)
      root = my_app("device(Devices::IMU, as: 'imu')\n", CONF => conf)
      [load_app(root, problems: true, everything: true).errors.first, root]
    ensure
      @loaded_apps&.pop&.unload
    end

    def test_chain_merges_the_sections_it_names_into_the_section
      conf = <<~YAML
        --- name:default
        rate: 10
        --- name:bench chain:default
        device: /dev/bench
        --- name:slow chain:default
        rate: 1
      YAML
      assert_equal({ 'rate' => 10, 'device' => '/dev/bench' }, properties(conf, %w[bench]))
      # As Rock's loader merges them, the chained sections' values win.
      assert_equal({ 'rate' => 10 }, properties(conf, %w[slow]))
    end

    def test_a_section_replaces_the_bundles_one_of_the_same_name_unless_it_merges
      bundle = "--- name:default\ndevice: /dev/bundle\nrate: 50\n--- name:lab\nrate: 5\n"
      assert_equal({ 'rate' => 7 }, properties("--- name:default\nrate: 7\n", %w[default], bundle_conf: bundle))
      assert_equal({ 'device' => '/dev/bundle', 'rate' => 7 },
                   properties("--- name:default merge:true\nrate: 7\n", %w[default], bundle_conf: bundle))
      # The bundle's sections the app does not declare are there too.
      assert_equal({ 'rate' => 5 }, properties("--- name:default\nrate: 7\n", %w[lab], bundle_conf: bundle))
    end

    def test_a_comment_on_a_header_line_is_refused_as_rock_refuses_it
      error, root = conf_error("--- name:default\nrate: 10\n--- name:fast # the quick one\nrate: 100\n")
      assert_reported error, /'#' on a section header is not one of its options \(name:, merge:, chain:\)/,
                      at: "#{CONF}:3", hint: /no comment on a header line: put it on the line above/, root: root
    end

    def test_an_unknown_header_option_is_refused
      error, root = conf_error("--- name:default merge:yes\nrate: 10\n")
      assert_reported error, /merge:yes on a section header: merge is true or false/, at: "#{CONF}:1", root: root
      error, root = conf_error("--- name:default order:1\nrate: 10\n")
      assert_reported error, /'order:1' on a section header is not one of its options/,
                      at: "#{CONF}:1", hint: /chain:other/, root: root
    end

    def test_a_chain_naming_a_section_not_declared_before
      error, root = conf_error("--- name:fast chain:defualt\nrate: 100\n--- name:default\nrate: 10\n")
      assert_reported error, /chain:defualt names the section 'defualt', which is not declared before this header/,
                      at: "#{CONF}:1", hint: /declare '--- name:defualt' above this section/, root: root
    end

    def test_the_first_header_may_leave_its_name_out
      assert_equal({ 'rate' => 3 }, properties("---\nrate: 3\n", %w[default]))
    end
  end
end
