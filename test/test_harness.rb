# frozen_string_literal: true

require 'helper'

module Syskit
  # `require 'syskit/test'`, `syskit test` and `rake test` in apps, run as
  # users run them: in a separate process.
  class TestHarness < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

    def syskit_test(app, *files)
      syskit_process('test', '--app', app, *files)
    end

    def test_the_seed_test_snippets_pass_as_written
      %w[non_demux demux nmea2000/seabots].each do |app|
        out, err, status = syskit_test(fixture('seed', app))
        assert status.success?, "#{app}:\n#{out}\n#{err}"
        assert_match(/0 failures, 0 errors/, out)
      end
    end

    def test_rake_test_in_the_example_apps
      %w[awesome_robot arm_lab].each do |app|
        out, err, status = rake_process('test', chdir: File.join(GEM_ROOT, 'examples', app))
        assert status.success?, "#{app}:\n#{out}\n#{err}"
        assert_match(/\d+ runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out, app)
      end
    end

    BROKEN_PROFILE = {
      'config/syskit.yml' => "name: MyApp\n",
      'models/devices/imu.rb' => "module MyApp\n  module Devices\n    device_type 'IMU'\n  end\nend\n",
      'models/orogen/imu.orogen' => "name 'imu'\ntask_context 'Task' do\nend\n",
      'models/orogen/imu.rb' => "Syskit.extend_model OroGen.imu.Task do\n  " \
                                "driver_for MyApp::Devices::IMU, as: 'imu'\nend\n",
      'models/profiles/base.rb' => <<~RUBY,
        using_task_library 'imu'

        module MyApp
          module Profiles
            profile 'Base' do
              robot do
                device(Devices::IMU, as: 'imu')
              end
            end
          end
        end
      RUBY
      'config/robots/default.rb' => "# nothing deployed\n",
      'test/profiles/test_base.rb' => <<~RUBY
        require 'syskit/test'

        module MyApp
          module Profiles
            describe Base do
              it('is self contained') { is_self_contained }
              it('can be deployed') { can_deploy }
            end
          end
        end
      RUBY
    }.freeze

    def test_a_profile_test_fails_with_the_generator_message
      app = write_app(BROKEN_PROFILE, name: 'my_app')
      out, _err, status = syskit_test(app)
      refute status.success?
      assert_match(/1 failures, 0 errors/, out)
      assert_match(%r{models/profiles/base\.rb:7: no deployed task can run imu::Task, the driver of device 'imu'}, out)
      assert_match(%r{hint: add to config/robots/default\.rb: Syskit\.conf\.use_deployment OroGen\.imu\.Task => 'imu'},
                   out)
    end

    def test_stubs_do_not_leak_from_one_test_to_the_next
      files = BROKEN_PROFILE.merge(
        'config/robots/default.rb' => "Syskit.conf.use_deployment OroGen.imu.Task => 'imu'\n",
        'test/test_stubs.rb' => <<~RUBY
          require 'syskit/test'

          module MyApp
            describe OroGen.imu.Task do
              2.times do |i|
                it "stubs the device 'imu' again (\#{i})" do
                  dev = syskit_stub_device(Devices::IMU, as: 'imu')
                  assert_same dev, syskit_stub_deploy_and_configure(dev).imu_dev
                  assert_equal ['imu'], syskit_stub_plan.devices.map(&:name)
                end
              end

              it 'stubs the devices of a task model given instead of a device, as Syskit does' do
                assert_equal MyApp::Devices::IMU, syskit_stub_deploy_and_configure(OroGen.imu.Task).imu_dev.model
              end
            end
          end
        RUBY
      )
      app = write_app(files, name: 'my_app')
      out, err, status = syskit_test(app, File.join(app, 'test', 'test_stubs.rb'))
      assert status.success?, "#{out}\n#{err}"
      assert_match(/3 runs, \d+ assertions, 0 failures, 0 errors/, out)
    end

    def test_an_app_with_problems_is_reported_before_its_tests_run
      app = write_app(BROKEN_PROFILE.merge('models/devices/imu.rb' => "device_type 'imu'\n"), name: 'my_app')
      # The test file describes a profile the broken files left undefined:
      # the app's problems come first, and the tests say what they miss
      # (the name is Rock's ::Base then, as in Rock).
      out, err, status = syskit_test(app)
      refute status.success?
      assert_match(%r{\Amodels/devices/imu\.rb:1: 'imu' is not a valid name for a device}, err)
      assert_match(/profile assertions need `describe SomeProfile do ... end`, not Base: the profile may not be/, out)
    end

    # A profile whose file stops at a typo after its device: its tests
    # selected by -n, and the run, never pass on the half that loaded.
    DEPLOYED_PROFILE = BROKEN_PROFILE.merge(
      'config/robots/default.rb' => "Syskit.conf.use_deployment OroGen.imu.Task => 'imu'\n"
    ).freeze

    def with_line_after_device(files, path, line)
      device = "        device(Devices::IMU, as: 'imu')\n"
      source = files.fetch(path).sub(device, "#{device}        #{line}\n")
      files.merge(path => source)
    end

    def test_a_test_of_a_profile_that_did_not_load_errors_at_the_load_error
      files = with_line_after_device(DEPLOYED_PROFILE, 'models/profiles/base.rb', 'Devices::Nope')
      app = write_app(files, name: 'my_app')
      out, err, status = syskit_test(app, '-n', '/deployed/')
      refute status.success?, out
      assert_match(%r{^models/profiles/base\.rb:8: uninitialized constant}, err)
      assert_match(/^1 runs, 0 assertions, 0 failures, 1 errors/, out)
      assert_match(/MyApp::Profiles::Base did not load completely, so this test cannot check it:\n.*base\.rb:8/, out)
      assert_match(/1 problem\(s\) loading the app or its test files .* the run fails whatever its tests say/, out)
    end

    def test_a_profile_that_requires_a_broken_file_cannot_pass_its_tests
      files = DEPLOYED_PROFILE.merge(
        'models/compositions/pair.rb' => "module MyApp\n  module Compositions\n    Nope.new\n  end\nend\n"
      )
      files['models/profiles/base.rb'] = "require 'models/compositions/pair'\n#{files['models/profiles/base.rb']}"
      out, _err, status = syskit_test(write_app(files, name: 'my_app'), '-n', '/self contained/')
      refute status.success?, out
      assert_match(/^1 runs, 0 assertions, 0 failures, 1 errors/, out)
      assert_match(%r{did not load completely, so this test cannot check it:\n.*models/compositions/pair\.rb:3}, out)
    end

    def test_a_load_error_fails_the_run_even_when_no_selected_test_uses_it
      files = DEPLOYED_PROFILE.merge('models/devices/other.rb' => "device_type 'other'\n")
      out, _err, status = syskit_test(write_app(files, name: 'my_app'), '-n', '/deployed/')
      refute status.success?, out
      assert_match(/^1 runs, \d+ assertions, 0 failures, 0 errors/, out)
      assert_match(/1 problem\(s\) loading the app or its test files/, out)
    end

    def test_a_test_file_that_does_not_load_fails_the_run
      files = DEPLOYED_PROFILE.merge('test/test_typo.rb' => "require 'syskit/test'\nMyApp::Nope\n")
      out, _err, status = syskit_test(write_app(files, name: 'my_app'), '-n', '/deployed/')
      refute status.success?, out
      assert_match(/^1 runs, \d+ assertions, 0 failures, 0 errors/, out)
    end

    def test_an_app_with_problems_runs_the_tests_that_do_not_depend_on_them
      deploy = "Syskit.conf.use_deployment OroGen.imu.Task => 'imu'\n"
      files = BROKEN_PROFILE.merge('models/devices/other.rb' => "device_type 'other'\n",
                                   'config/robots/default.rb' => deploy)
      out, _err, status = syskit_test(write_app(files, name: 'my_app'))
      refute status.success?
      assert_match(/^MyApp \(loading\)#test_the_app_loads_without_problems/, out)
      assert_match(%r{^models/devices/other\.rb:1: 'other' is not a valid name for a device}, out)
      assert_match(/^3 runs, \d+ assertions, 1 failures, 0 errors/, out)
    end
  end
end
