# frozen_string_literal: true

require 'helper'

module Syskit
  # A Rock app whose config/init.rb sets Roby.app.auto_load_models to
  # false (as common_models does) runs its tests with what its robot
  # configuration and its test files require, as Roby loads it: a model
  # file nothing requires is not loaded, and its problems are not the
  # tests'. syskit check still loads, and reports, every file.
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

    def test_without_the_setting_every_model_file_is_loaded_for_the_tests
      app = write_app(FILES.merge('config/init.rb' => "Roby.app.using 'syskit'\n"), name: 'dock')
      out, = syskit_process('test', '--app', app, 'test/services/test_pose.rb', chdir: app)
      assert_match(/^2 runs, \d+ assertions, 1 failures, 0 errors, 0 skips$/, out)
      assert_match(/Dock has 1 problem\(s\)/, out)
    end
  end
end
