# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # A profile's definition deployed on its own in a test, as Syskit's
  # users write it (+syskit_stub_and_deploy(Nav.nav_def)+): it is made in
  # its profile's selections, the robot's devices by device model and the
  # profile's own use; and a profile using it reaches its devices.
  class TestProfileDefinitionHarness < Minitest::Test
    include CompositionTestHelper

    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

    MODELS = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          # A position from the GPS device, whichever the profile has.
          class Fix < Syskit::Composition
            add Devices::GPS, as: 'receiver'
            export receiver_child.position_port, as: 'pose'
            provides Services::Pose, as: 'pose'
          end

          class Steer < Syskit::Composition
            add Services::Pose, as: 'pose'
            add OroGen.rig.Follower, as: 'follower'
            add Devices::Wheel, as: 'wheel'
            pose_child.pose_port.connect_to follower_child.pose_port
            follower_child.command_port.connect_to wheel_child.cmd_port
          end
        end

        module Profiles
          profile 'Nav' do
            robot do
              device Devices::GPS, as: 'antenna'
              device(Devices::Wheel, as: 'rear_wheel').prefer_deployed_tasks('left_wheel')
            end
            use 'wheel' => rear_wheel_dev
            define 'nav', Compositions::Steer.use('pose' => Compositions::Fix)
          end

          profile 'Mission' do
            use_profile Nav
          end
        end
      end
    RUBY

    NAV_TEST = <<~RUBY
      require 'models/profiles/nav'
      module Rig
        module Profiles
          describe Nav do
            it 'deploys a definition in its profile' do
              cmp = syskit_stub_and_deploy(Nav.nav_def)
              receiver = cmp.pose_child.receiver_child
              assert_equal 'antenna', receiver.robot_device.name
              assert_kind_of Devices::GPS, receiver
              assert_equal 'rear_wheel', cmp.wheel_child.robot_device.name
              assert_equal 'nav', Nav.nav_def.name
            end

            it 'gives a profile using it its devices' do
              assert_equal 'antenna', Mission.antenna_dev.device.name
              assert_same Nav.antenna_dev.device, Mission.antenna_dev.device
              assert_equal 'nav', Mission.nav_def.name
            end
          end
        end
      end
    RUBY

    def test_a_definition_deployed_in_a_test_has_its_profiles_selections
      app = rig_app({ 'models/profiles/nav.rb' => MODELS, 'test/profiles/test_nav.rb' => NAV_TEST })
      out, err, status = syskit_process('test', 'test/profiles/test_nav.rb', chdir: app)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/2 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out)
    end
  end
end
