# frozen_string_literal: true

require 'helper'

module Syskit
  # A Rock app whose config/init.rb sets Roby.app.auto_load_models to
  # false (as common_models does) runs its tests with what its robot
  # configuration and its test files require, and plans what its robot
  # configuration requires, as Roby loads it: a model file nothing
  # requires is not loaded, and its problems are not the tests' or the
  # plan's. syskit check still loads, and reports, every file.
  class TestAutoLoadModels < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!
    FILES = {
      'config/syskit.yml' => "name: Dock\n",
      'config/init.rb' => <<~RUBY,
        Roby.app.using 'syskit'
        # Roby.app.auto_load_models = true
        Roby.app.auto_load_models = false
      RUBY
      'models/services/pose.rb' => <<~RUBY,
        module Dock
          module Services
            data_service_type 'Pose' do
              output_port 'pose', '/double'
            end
          end
        end
      RUBY
      # A file of older times, which nothing requires any more.
      'models/blueprints/old.rb' => "module Dock\n  OLD = Stale::Name\nend\n",
      'test/services/test_pose.rb' => <<~RUBY,
        require 'models/services/pose'
        module Dock
          module Services
            describe Pose do
              it('has its port') { assert Pose.find_port('pose') }
            end
          end
        end
      RUBY
      'test/blueprints/test_old.rb' => <<~RUBY
        require 'models/blueprints/old'
        describe 'the old blueprint' do
          it('loads') { assert Dock::OLD }
        end
      RUBY
    }.freeze

    def test_tests_load_what_they_require
      app = write_app(FILES, name: 'dock')
      out, err, status = syskit_process('test', '--app', app, 'test/services/test_pose.rb', chdir: app)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^1 runs, 1 assertions, 0 failures, 0 errors, 0 skips$/, out)
    end

    def test_a_test_requiring_a_broken_file_fails_at_its_require
      app = write_app(FILES, name: 'dock')
      out, = syskit_process('test', '--app', app, 'test/blueprints/test_old.rb', chdir: app)
      assert_match(/^1 runs, 1 assertions, 1 failures, 0 errors, 0 skips$/, out)
      assert_match(%r{test/blueprints/test_old.rb \(loading\)}, out)
      assert_match(%r{models/blueprints/old.rb:2: uninitialized constant .*Stale}, out)
    end

    def test_check_loads_every_file
      app = write_app(FILES, name: 'dock')
      out, _err, status = syskit_process('check', '--app', app)
      assert_equal 1, status.exitstatus
      assert_match(%r{^models/blueprints/old.rb:2: uninitialized constant}, out)
    end

    # syskit plan (and doc, bus) load what the robot configuration requires,
    # as Roby does: a profile nothing requires is not there to plan, and
    # a stale file nothing requires does not stop the plan.
    def test_plan_loads_what_the_robot_configuration_requires
      app = my_app(nil, FILES.slice('config/init.rb', 'models/blueprints/old.rb').merge(
                          'config/syskit.yml' => "name: MyApp\nacronyms: [IMU]\n",
                          'models/profiles/base.rb' => PROFILE.call('Base'),
                          'models/profiles/unused.rb' => PROFILE.call('Unused'),
                          'config/robots/default.rb' => <<~RUBY
                            Robot.requires do
                              require 'models/profiles/base'
                            end
                            using_task_library 'imu'
                            Syskit.conf.use_deployment OroGen.imu.Task => 'imu'
                          RUBY
                        ))
      out, err, status = syskit_process('plan', '--app', app)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^Plan of MyApp::Profiles::Base on robot 'default'/, out)
      _, err, status = syskit_process('plan', 'Unused', '--app', app)
      assert_equal 1, status.exitstatus
      assert_match(/no profile .*Unused/i, err)
    end

    PROFILE = lambda do |name|
      <<~RUBY
        using_task_library 'imu'
        module MyApp
          module Profiles
            profile '#{name}' do
              robot do
                device MyApp::Devices::IMU, as: 'imu'
              end
            end
          end
        end
      RUBY
    end

    def test_without_the_setting_every_model_file_is_loaded_for_the_tests
      app = write_app(FILES.merge('config/init.rb' => "Roby.app.using 'syskit'\n"), name: 'dock')
      out, = syskit_process('test', '--app', app, 'test/services/test_pose.rb', chdir: app)
      assert_match(/^2 runs, \d+ assertions, 1 failures, 0 errors, 0 skips$/, out)
      assert_match(/Dock has 1 problem\(s\)/, out)
    end
  end
end
