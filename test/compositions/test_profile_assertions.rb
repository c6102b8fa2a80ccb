# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # The profile assertions' arguments and options, as Syskit's: profiles
  # and requirements as actions, exclude:, together_with:, the _together
  # and assert_ forms, tags of other profiles. Run with `syskit test`.
  class TestProfileAssertions < Minitest::Test
    include CompositionTestHelper

    parallelize_me!

    FOLLOW = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          class Follow < Syskit::Composition
            add Services::Pose, as: 'pose'
            add OroGen.rig.Follower, as: 'follower'
            add Devices::Wheel, as: 'wheel'
            pose_child.pose_port.connect_to follower_child.pose_port
            follower_child.command_port.connect_to wheel_child.cmd_port
          end
        end
      end
    RUBY

    PROFILES = <<~RUBY
      require 'models/compositions/follow'
      module Rig
        module Profiles
          profile 'Generic' do
            tag 'localization', Services::Pose
            define 'follow', Compositions::Follow.use('pose' => localization_tag)
          end
          profile 'Base' do
            robot do
              device Devices::GPS, as: 'gps'
              device(Devices::Wheel, as: 'left_wheel').prefer_deployed_tasks('left_wheel')
            end
            define 'follow', Compositions::Follow.use('pose' => gps_dev, 'wheel' => left_wheel_dev)
          end
          profile 'Unfinished' do
            define 'follow', Compositions::Follow
          end
          profile 'Mixed' do
            define 'follow', Compositions::Follow.use('pose' => Generic.localization_tag)
          end
        end
      end
    RUBY

    TEST = <<~RUBY
      require 'models/profiles/all'
      module Rig
        module Profiles
          describe Base do
            it { assert_can_deploy(Base.follow_def) }
            it { can_instanciate(exclude: [Base.follow_def]) }
            it { can_instanciate(Unfinished, exclude: Unfinished.follow_def) }
            it { can_instanciate(Compositions::Follow.use('pose' => Base.gps_dev, 'wheel' => Base.left_wheel_dev)) }
            it { assert_can_deploy_together(Base.follow_def, Base.gps_dev) }
            it { can_deploy(Base.gps_dev, together_with: OroGen.rig.Tracker) }
            it { can_deploy(Base.gps_dev, together_with: Unfinished.follow_def) }
          end
          describe Generic do
            it { assert_is_self_contained }
          end
          describe Mixed do
            it { is_self_contained }
          end
        end
      end
    RUBY

    def test_profile_assertions_take_profiles_requirements_and_options
      app = rig_app({ 'models/compositions/follow.rb' => FOLLOW, 'models/profiles/all.rb' => PROFILES,
                      'test/profiles/test_all.rb' => TEST })
      out, err, status = syskit_process('test', 'test/profiles/test_all.rb', chdir: app)
      refute status.success?
      assert_match(/9 runs, \d+ assertions, 3 failures, 0 errors, 0 skips/, out, err)
      # Excluding every action leaves nothing to check: that fails too.
      assert_match(/test_all.rb:7\]:\ncan_instanciate: every action of Rig::Profiles::Unfinished is excluded, so there/,
                   out)
      assert_match(%r{test_all.rb:11\]:\nmodels/profiles/all.rb:16: the child 'pose' of Rig::Compositions::Follow}, out)
      assert_match(%r{test_all.rb:17\]:\nmodels/profiles/all.rb:19: .*Generic.localization_tag selects nothing}, out)
    end
  end
end
