# frozen_string_literal: true

require 'helper'

module Syskit
  # Messages about real Rock files that used to point the wrong way
  # (issue 23), and how files of several bundles find each other.
  class TestRockFileMessages < Minitest::Test
    # sonar.rb fails before it defines Sonar.
    SONAR = <<~RUBY
      module MyApp
        module Services
          data_service_type 'Ping' do
            output_port 'ping', '/dobule'
          end
          data_service_type 'Sonar'
        end
      end
    RUBY

    # echo.rb, loaded after sonar.rb failed, requires it: the require
    # does nothing, and Sonar is not there.
    def test_a_constant_of_a_required_file_that_failed_to_load
      echo = "require 'models/services/sonar'\nmodule MyApp\n  module Devices\n    device_type 'Echo' do\n      " \
             "provides Services::Sonar\n    end\n  end\nend\n"
      root = my_app(nil, 'models/services/sonar.rb' => SONAR, 'models/tools/echo.rb' => echo)
      errors = load_app(root, problems: true).errors
      sonar = errors.find { |e| e.location.path.end_with?('sonar.rb') }
      assert_reported sonar, %r{unknown type /dobule}, at: 'models/services/sonar.rb:4', root: root
      echo = errors.find { |e| e.location.path.end_with?('echo.rb') }
      hint = 'Services::Sonar is defined in models/services/sonar.rb, which failed to load ' \
             '(models/services/sonar.rb:4): fix that error first'
      assert_reported echo, /uninitialized constant MyApp::Services::Sonar/, at: 'models/tools/echo.rb:5',
                                                                             hint: Regexp.new(Regexp.escape(hint)),
                                                                             root: root
    end

    def test_a_typo_in_the_case_of_a_loaded_constant_gets_a_spelling_hint
      root = my_app("device(Devices::MC200, as: 'motor')\n", 'models/devices/mc200.rb' => <<~RUBY)
        module MyApp
          module Devices
            device_type 'Mc200'
          end
        end
      RUBY
      error = load_problem(root)
      assert_reported error, /uninitialized constant MyApp::Devices::MC200/, at: 'models/profiles/base.rb:9',
                                                                             hint: /did you mean.*Mc200/, root: root
      refute_match(/does not require/, error.hint)
    end

    def test_a_required_argument_that_is_not_set
      root = my_app("device(Devices::IMU, as: 'imu')\n", 'models/orogen/imu.rb' => <<~RUBY)
        require 'models/devices/imu'
        Syskit.extend_model OroGen.imu.Task do
          argument :frame
          argument :rate_limit, default: nil
          driver_for MyApp::Devices::IMU, as: 'imu'

          def configure
            super
            properties.device = "/dev/\#{rate_limit.inspect}"
            properties.device = frame
          end
        end
      RUBY
      load_app(root)
      error = assert_raises(ConfigurationError) do
        Network::Generator.plan_profile(Syskit.app, MyApp::Profiles::Base.syskit_profile)
      end
      assert_reported error, Regexp.new("in imu::Task's configure for device 'imu': argument 'frame' of imu::Task " \
                                        'is not set \(declared at models/orogen/imu.rb:3\)'),
                      at: 'models/orogen/imu.rb:10', hint: /with_arguments\(frame: \.\.\.\)/, root: root
    end

    def test_a_port_declared_with_a_typedef_shows_both_names
      root = my_app("device(Devices::IMU, as: 'imu')\n", 'models/orogen/imu.orogen' => <<~RUBY)
        name 'imu'
        import_types_from 'base'
        task_context 'Task' do
          property 'device', '/std/string', '/dev/ttyUSB0'
          property 'rate', 'int', 100
          input_port 'cmd', '/base/commands/Joints'
          output_port 'samples', '/base/samples/IMUSensors'
        end
      RUBY
      load_app(root)
      plan = Network::Generator.plan_profile(Syskit.app, MyApp::Profiles::Base.syskit_profile).plan
      assert_match(%r{ cmd  input /base/commands/Joints \(= /base/samples/Joints\)$}, Render::Text.render(plan))
      assert_match(%r{ samples  output /base/samples/IMUSensors$}, Render::Text.render(plan))
      assert_equal "input port 'cmd' (/base/commands/Joints (= /base/samples/Joints))",
                   OroGen.imu.Task.ports['cmd'].to_s
    end

    # Ruby takes 'models/services/pose' as loaded once any directory of the
    # load path has one loaded: with two bundles, the app's own would never
    # load after the other bundle's.
    def test_a_require_finds_the_app_file_even_when_a_bundle_has_one_of_the_same_name
      parts = write_app({ 'config/syskit.yml' => "name: Parts\n",
                          'models/services/pose.rb' => "module Parts\n  data_service_type 'Pose'\nend\n" },
                        name: 'parts')
      root = my_app(nil, 'config/syskit.yml' => "name: MyApp\nbundles: [#{parts}]\n",
                         'models/devices/a_first.rb' => "require 'parts/models/services/pose'\n",
                         'models/services/pose.rb' => "module MyApp\n  data_service_type 'Pose'\nend\n",
                         'models/devices/b_second.rb' => "require 'models/services/pose'\nMyApp::Pose\n")
      load_app(root)
      assert_kind_of Models::DataServiceModel, MyApp::Pose
      assert_kind_of Models::DataServiceModel, Parts::Pose
    end

    def test_rock_the_old_name_of_common_models
      root = my_app(nil, 'models/devices/old.rb' => <<~RUBY)
        require 'rock/models/services/pose'
        module MyApp
          module Devices
            device_type 'Old' do
              provides Rock::Services::Pose
            end
          end
        end
      RUBY
      app = load_app(root, problems: true)
      warning = app.problems.grep(Warning).first
      assert_reported warning, Regexp.new("rock/models/services/pose is common_models' file under its name before " \
                                          "2017 \\(the 'rock' bundle\\), and common_models has no " \
                                          'models/services/pose either: not loaded'),
                      at: 'models/devices/old.rb:1', root: root
      assert_reported app.errors.first, /uninitialized constant MyApp::Devices::Rock/,
                      at: 'models/devices/old.rb:5', hint: /Rock:: is common_models under its name before 2017: /,
                      root: root
    end

    def test_parent_of_a_data_service_must_be_a_data_service
      root = my_app(nil, 'models/services/x.rb' => "module MyApp\n  data_service_type 'X', parent: 3\nend\n")
      assert_reported load_problem(root), /parent: expects a data service model, got 3/,
                      at: 'models/services/x.rb:2', root: root
    end
  end
end
