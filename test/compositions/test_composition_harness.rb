# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Composition and profile tests written as Syskit users write them, run
  # with `syskit test` in a separate process.
  class TestCompositionHarness < Minitest::Test
    include CompositionTestHelper

    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
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
              cmp = syskit_stub_and_deploy(Follow, recursive: true)
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

    # A composition whose Ruby code computes with Eigen values and reads
    # its arguments, as pose predicates in Rock's bundles do.
    NEAR = <<~RUBY
      require 'models/devices/rover'
      module Rig
        module Compositions
          class Near < Syskit::Composition
            argument :target
            argument :tolerance
            add Services::Pose, as: 'pose'

            def near?(sample)
              offset = target.position - sample.position
              turn = (target.orientation.inverse * sample.orientation).to_euler
              3.times.all? { |i| offset[i].abs <= tolerance[i] } && turn[0].abs <= tolerance[3]
            end
          end
        end
      end
    RUBY

    NEAR_TEST = <<~RUBY
      require 'models/compositions/near'
      module Rig
        module Compositions
          describe Near do
            before do
              @target = Types.base.Pose.new(position: Eigen::Vector3.Zero, orientation: Eigen::Quaternion.Identity)
              @near = Near.new(target: @target)
            end

            def pose(x, yaw)
              Types.base.Pose.new(position: Eigen::Vector3.new(x, 0, 0),
                                  orientation: Eigen::Quaternion.from_angle_axis(yaw, Eigen::Vector3.UnitZ))
            end

            it 'compares positions and headings within the tolerance set on it' do
              @near.tolerance = [0.5, 0.5, 0.5, 0.2]
              assert @near.near?(pose(0.4, 0.1))
              refute @near.near?(pose(0.6, 0.1))
              refute @near.near?(pose(0.4, -0.3))
            end

            it "has the rotations of Rock's Eigen bindings" do
              q = Eigen::Quaternion.from_euler(Eigen::Vector3.new(0.3, -0.2, 0.1), 2, 1, 0)
              assert q.to_euler.approx?(Eigen::Vector3.new(0.3, -0.2, 0.1), 1e-9)
              assert (q * Eigen::Vector3.UnitX).approx?(q.transform(Eigen::Vector3.UnitX))
              assert (q * q.inverse).approx?(Eigen::Quaternion.Identity, 1e-12)
              assert_equal Eigen::Vector3.Unset, Eigen::Vector3.Unset
              assert Base.unset?(Eigen::Vector3.Unset[1])
            end
          end
        end
      end
    RUBY

    # Task models made in a test, as Syskit's tests make them.
    RUBY_MODELS_TEST = <<~RUBY.freeze
      require 'models/compositions/follow'
      module Rig
        module Compositions
          describe Follow do
            it 'takes task models made in Ruby as its children' do
              source = Syskit::TaskContext.new_submodel(name: 'Source') do
                output_port 'pose', '#{RBS}'
                provides Services::Pose, as: 'pose'
              end
              follower = OroGen.rig.Follower.new_submodel { output_port 'debug', '/double' }
              cmp = syskit_stub_and_deploy(Follow.use('pose' => source, 'follower' => follower))
              assert_equal 'Source', cmp.pose_child.model.name
              assert cmp.pose_child.pose_port.connected_to?(cmp.follower_child.pose_port)
              assert cmp.follower_child.model <= OroGen.rig.Follower
              assert cmp.follower_child.model.find_port('debug')
              assert_equal 1.0, cmp.follower_child.model.new.properties.gain
            end
          end
        end
      end
    RUBY

    # Configuration sections a test stubs, for itself only.
    CONF_TEST = <<~RUBY
      require 'models/compositions/follow'
      module Rig
        module Compositions
          describe Follow do
            it 'configures its children with the stubbed sections' do
              syskit_stub_conf(OroGen.rig.Follower, 'default', data: { 'gain' => 2.5 })
              syskit_stub_conf(OroGen.rig.Follower, 'fast', data: { gain: 4.0 })
              cmp = syskit_stub_deploy_and_configure(Follow)
              assert_equal 2.5, cmp.follower_child.properties.gain
              cmp = syskit_stub_deploy_and_configure(Follow.use('follower' => OroGen.rig.Follower.with_conf('default', 'fast')))
              assert_equal 4.0, cmp.follower_child.properties.gain
            end

            it 'has the sections of the files again in the next test' do
              assert_equal 1.0, syskit_stub_deploy_and_configure(Follow).follower_child.properties.gain
            end

            # As Syskit's stubs: a section no file has is empty in a test.
            it 'gives its children the sections they ask for' do
              night = Follow.use('follower' => OroGen.rig.Follower.with_conf('default', 'night'))
              assert_equal 1.0, syskit_stub_deploy_and_configure(night).follower_child.properties.gain
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

    # A profile leaving its tag to the profiles that use it.
    GENERIC = <<~RUBY
      require 'models/compositions/follow'
      module Rig
        module Profiles
          profile 'Generic' do
            tag 'localization', Services::Pose
            define 'follow', Compositions::Follow.use('pose' => localization_tag)
          end
        end
      end
    RUBY

    GENERIC_TEST = <<~RUBY
      require 'models/profiles/generic'
      module Rig
        module Profiles
          describe Generic do
            it { is_self_contained }
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
      syskit_process('test', *args, chdir: app)
    end

    def test_composition_tests_run_with_the_stubs
      out, err, status = syskit_test(harness_app, 'test/compositions/test_follow.rb')
      assert status.success?, "#{out}\n#{err}"
      assert_match(/5 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out)
    end

    def test_compositions_compute_with_eigen_values_and_their_arguments
      app = rig_app({ 'models/compositions/near.rb' => "require 'base/float'\n#{NEAR}",
                      'test/compositions/test_near.rb' => NEAR_TEST })
      out, err, status = syskit_test(app, 'test/compositions/test_near.rb')
      assert status.success?, "#{out}\n#{err}"
      assert_match(/2 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out)
    end

    def test_task_models_made_in_ruby_in_a_test
      app = rig_app({ 'models/compositions/follow.rb' => FOLLOW,
                      'test/compositions/test_models.rb' => RUBY_MODELS_TEST })
      out, err, status = syskit_test(app, 'test/compositions/test_models.rb')
      assert status.success?, "#{out}\n#{err}"
      assert_match(/1 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out)
    end

    def test_configuration_sections_stubbed_by_a_test
      app = rig_app({ 'models/compositions/follow.rb' => FOLLOW, 'test/compositions/test_conf.rb' => CONF_TEST })
      out, err, status = syskit_test(app, 'test/compositions/test_conf.rb', '--seed', '1')
      assert status.success?, "#{out}\n#{err}"
      assert_match(/3 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out)
      out, err, status = syskit_test(app, 'test/compositions/test_conf.rb', '--seed', '2')
      assert status.success?, "#{out}\n#{err}"
    end

    # As in Syskit: is_self_contained accepts the profile's own tags, the
    # assertions that need a concrete network do not.
    def test_is_self_contained_leaves_a_profile_s_own_tags_to_the_profiles_using_it
      app = rig_app({ 'models/compositions/follow.rb' => FOLLOW, 'models/profiles/generic.rb' => GENERIC,
                      'test/profiles/test_generic.rb' => GENERIC_TEST })
      out, err, status = syskit_test(app, 'test/profiles/test_generic.rb')
      refute status.success?
      assert_match(/2 runs, \d+ assertions, 1 failures, 0 errors, 0 skips/, out, err)
      assert_match(%r{test_generic.rb:6\]:\nmodels/profiles/generic.rb:6: .*localization_tag selects nothing}, out)
    end

    def test_profile_assertions_cover_definitions
      out, err, status = syskit_test(harness_app, 'test/profiles/test_base.rb')
      refute status.success?
      assert_match(/6 runs, \d+ assertions, 1 failures, 0 errors, 0 skips/, out, err)
      assert_match(%r{models/profiles/base.rb:13: the child 'pose' of Rig::Compositions::Follow \(follow.pose\) }, out)
    end
  end
end
