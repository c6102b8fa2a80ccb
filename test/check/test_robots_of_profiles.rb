# frozen_string_literal: true

require 'helper'

module Syskit
  module Checks
    # `syskit check` generates a profile on the robots that load it, as
    # Roby loads a robot: a robot whose configuration neither requires the
    # profile's file nor uses the profile deploys none of its tasks, and
    # checking the profile there would only report false errors.
    class TestRobotsOfProfiles < Minitest::Test
      # An IMU profile for each way a robot may name it, and three robots:
      # +lab+ requires one profile (through a file that requires it),
      # +field+ uses one in its action interface, +default+ names none.
      def imu_profile(name)
        <<~RUBY
          using_task_library 'imu'

          module MyApp
            module Profiles
              profile '#{name}' do
                robot do
                  device(MyApp::Devices::IMU, as: 'imu')
                end
              end
            end
          end
        RUBY
      end

      def two_robots_app
        profile = method(:imu_profile)
        my_app(nil,
               'models/profiles/lab.rb' => profile['Lab'],
               'models/profiles/field.rb' => profile['Field'],
               'models/profiles/loose.rb' => profile['Loose'],
               'models/profiles/lab_setup.rb' => "require 'models/profiles/lab'\n",
               'config/robots/default.rb' => "Robot.requires do\nend\n",
               'config/robots/lab.rb' => <<~RUBY,
                 Robot.requires do
                   require 'models/profiles/lab_setup'
                   Syskit.conf.use_deployment OroGen.imu.Task => 'lab_imu'
                 end
               RUBY
               'config/robots/field.rb' => <<~RUBY)
                 Robot.requires do
                   Syskit.conf.use_deployment OroGen.imu.Task => 'field_imu'
                 end

                 Robot.actions do
                   use_profile MyApp::Profiles::Field
                   use_library MyApp::Actions::Anything
                 end
               RUBY
      end

      def test_a_profile_is_checked_on_the_robots_that_load_it
        app = App.new(two_robots_app)
        report = Check.new(app).run
        robots = app.profiles.values.to_h { |p| [p.name.split('::').last, report.robots_of(p)] }
        assert_equal({ 'Lab' => %w[lab], 'Field' => %w[field], 'Loose' => %w[default field lab] },
                     robots.transform_values(&:sort))
      ensure
        app&.unload
      end

      # Only the profile no robot names is checked on default, where
      # nothing is deployed.
      def test_only_a_profile_no_robot_names_is_checked_everywhere
        out, _, status = run_cli('check', '--app', two_robots_app)
        assert_equal 1, status, out
        errors = out.lines.grep(/no deployed task can run/)
        assert_equal 1, errors.size, out
        assert_match(%r{\Amodels/profiles/loose.rb:\d+: .* on robot 'default'}, errors.first)
      end
    end
  end
end
