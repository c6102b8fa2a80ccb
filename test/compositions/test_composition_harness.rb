# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'open3'
require 'rbconfig'

module Syskit
  # Composition and profile tests written as Syskit users write them, run
  # with `syskit test` in a separate process.
  class TestCompositionHarness < Minitest::Test
    include CompositionTestHelper

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

    PROFILE = <<~RUBY
      require 'models/compositions/follow'
      using_task_library 'rig'
      module Rig
        module Profiles
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
        end
      end
    RUBY

    COMPOSITION_TEST = <<~RUBY
      require 'models/compositions/follow'
      module Rig
        module Compositions
          describe Follow do
            it 'connects the selected pose source to the follower' do
              cmp = syskit_stub_and_deploy(Follow.use('pose' => OroGen.rig.Tracker.rear_pose_srv))
              assert_kind_of OroGen.rig.Tracker, cmp.pose_child
              assert cmp.pose_child.rear_port.connected_to?(cmp.follower_child.pose_port)
              refute cmp.pose_child.front_port.connected_to?(cmp.follower_child.pose_port)
              assert_equal %w[follower pose wheel], cmp.each_child.map { |_, info| info[:role] }.sort
            end

            it 'stubs what nothing selects' do
              cmp = syskit_stub_and_deploy(Follow)
              assert cmp.pose_child.model.fullfills?(Services::Pose)
              assert_same Devices::Wheel, cmp.wheel_child.robot_device.model
              assert cmp.follower_child.command_port.connected_to?(cmp.wheel_child.cmd_port)
            end

            it 'narrows on specializations' do
              srv = Syskit::DataService.new_submodel(name: 'Extra') { output_port 'extra', '/double' }
              Follow.specialize(Follow.pose_child => srv)
              assert_same Follow, Follow.use('pose' => OroGen.rig.Tracker.front_pose_srv).narrow_model
            end

            it 'configures what it stubs' do
              cmp = syskit_stub_deploy_and_configure(Follow)
              assert_equal 1.0, cmp.follower_child.properties.gain
            end

            it 'makes test types and clears test models' do
              type = stub_type '/TestCommand'
              Services.data_service_type('TestCommandSrv') { input_port 'cmd', type }
              assert Services.const_defined?(:TestCommandSrv)
              clear_newly_defined_models
              refute Services.const_defined?(:TestCommandSrv)
            end
          end
        end
      end
    RUBY

    PROFILE_TEST = <<~RUBY
      require 'models/profiles/base'
      module Rig
        module Profiles
          describe Base do
            it { is_self_contained }
            it { can_instanciate }
            it { can_deploy }
            it { can_deploy(Base.follow_def) }
            it { can_configure }
          end
          describe Unfinished do
            it { can_instanciate }
          end
        end
      end
    RUBY

    def harness_app
      rig_app({ 'models/compositions/follow.rb' => FOLLOW, 'models/profiles/base.rb' => PROFILE,
                'test/compositions/test_follow.rb' => COMPOSITION_TEST, 'test/profiles/test_base.rb' => PROFILE_TEST })
    end

    def syskit_test(app, *args)
      Open3.capture3(RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), 'test', *args, chdir: app)
    end

    def test_composition_tests_run_with_the_stubs
      out, err, status = syskit_test(harness_app, 'test/compositions/test_follow.rb')
      assert status.success?, "#{out}\n#{err}"
      assert_match(/5 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out)
    end

    def test_profile_assertions_cover_definitions
      out, err, status = syskit_test(harness_app, 'test/profiles/test_base.rb')
      refute status.success?
      assert_match(/6 runs, \d+ assertions, 1 failures, 0 errors, 0 skips/, out, err)
      assert_match(%r{models/profiles/base.rb:13: the child 'pose' of Rig::Compositions::Follow \(follow.pose\) }, out)
    end
  end
end
