# frozen_string_literal: true

require 'helper'
require 'open3'
require 'rbconfig'

module Syskit
  # What real Rock files name besides the model layer (issue 23):
  # test/fixtures/rock/harbor is a bundle written in those forms: utilrb's
  # loggers and option checks, Set, Eigen values, Orocos and
  # Syskit::Deployment in tests, Roby robot tests, a MetaRuby model class,
  # oroGen's digit port names, triggered_on and plugin types, base types
  # built with Rock's constructors, an undescribed typekit, and a require of
  # common_models under its old name.
  class TestRockRuntimeNames < Minitest::Test
    HARBOR = File.join(FIXTURES, 'rock', 'harbor')

    def test_the_bundle_checks_with_one_warning_per_construct
      out, _, status = run_cli('check', '--app', HARBOR)
      assert_equal 0, status, out
      warnings = out.lines.grep(/: warning: /).map(&:strip)
      assert_equal 4, warnings.size, out
      assert_match(%r{\Amodels/devices/winch.rb:1: warning: rock/models/devices/bus/can is common_models' file },
                   warnings[0])
      assert_match(/winch.orogen:15: warning: spatio_temporal \(envire's oroGen plugin\)/, out)
      assert_match(Regexp.new('winch.orogen:16: warning: /drum/Status is taken as opaque: no typekit describes ' \
                              '/drum/, and the typekit winch_types, imported without a description, may define it'),
                   out)
    end

    def test_its_tests_pass_and_what_needs_the_runtime_is_skipped
      out, err, status = Open3.capture3(RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), 'test', '--app', HARBOR,
                                        '-v')
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^14 runs, \d+ assertions, 0 failures, 0 errors, 6 skips$/, out)
      assert_match(/^use_deployment needs Syskit's runtime/, out)
      assert_match(/^expect_execution_default_timeout= needs Syskit's runtime/, out)
      assert_match(/^execute_robot_controller needs Syskit's runtime/, out)
      assert_match(/^syskit_configure needs Syskit's runtime/, out)
      assert_match(/^Syskit::Deployment \(a running process\) needs Syskit's runtime/, out)
      assert_match(/^Orocos::Test::Component starts components: needs Orocos' runtime/, out)
    end

    def test_orogen_forms_of_real_packages
      load_app(HARBOR)
      task = OroGen.winch.Task
      assert_equal %w[3d_tension cmd depth drum profile state], task.spec.ports.keys.sort
      assert_equal '/winch_types/Profile', task.find_port('profile').type.name
      assert_predicate task.find_port('drum').type, :opaque?
      assert_equal %w[gauge], task.dynamic_service_names
    end

    def test_metaruby_model_classes
      load_app(HARBOR)
      axis = Harbor::Services::Control::Axis
      # HeaveCommand, made from the heave axis, is a submodel of Axis too.
      assert_equal [:surge, :heave, nil], axis.each_submodel.map(&:axis)
      heave = axis.for(:heave)
      assert_same heave, Harbor::Services::HeaveCommand.supermodel
      assert_includes axis.each_submodel.to_a, Harbor::Services::HeaveCommand, 'submodels of submodels count too'
      assert_equal 'Harbor::Services::Control::Axis(heave)', heave.short_name
    end

    def test_syskit_stub_device_forwards_the_device_settings_and_refuses_others
      test = <<~RUBY
        describe 'stubs' do
          it('takes the settings of a device') do
            dev = syskit_stub_device(Stubs::Devices::Probe, as: 'probe', doc: 'the probe', burst: 3)
            assert_equal ['the probe', 3], [dev.doc, dev.burst]
          end
          it('refuses an option it does not know') do
            syskit_stub_device(Stubs::Devices::Probe, perod: 0.1)
          end
        end
      RUBY
      probe = "module Stubs\n  module Devices\n    device_type 'Probe'\n  end\nend\n"
      app = write_app({ 'config/syskit.yml' => "name: Stubs\n", 'test/test_stub.rb' => test,
                        'models/devices/probe.rb' => probe })
      out, = Open3.capture3(RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), 'test', '--app', app)
      assert_match(/^2 runs, \d+ assertions, 0 failures, 1 errors, 0 skips$/, out)
      assert_match(/syskit_stub_device: unknown option\(s\) perod: \(did you mean 'period'\?\)/, out)
    end
  end
end
