# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # What composition children may be given or ask for: optional children,
  # siblings, delayed arguments, named configurations, drivers and their
  # devices, buffered inputs, documentation.
  class TestCompositionChildren < Minitest::Test
    include CompositionTestHelper

    def test_optional_children_without_a_selection_are_left_out
      files = { 'models/compositions/maybe.rb' => <<~RUBY }
        require 'models/devices/rover'
        using_task_library 'rig'
        module Rig
          module Compositions
            class Maybe < Syskit::Composition
              add OroGen.rig.Follower, as: 'follower'
              add_optional Services::Pose, as: 'pose'
              pose_child.pose_port.connect_to follower_child.pose_port
            end
          end
        end
      RUBY
      app = follow_app(<<~RUBY, files)
        require 'models/compositions/maybe'
        profile 'Base' do
          define 'maybe', Compositions::Maybe
        end
      RUBY
      plan = plan_of(app, 'maybe_def')
      assert_equal({ 'follower' => 'follower' }, plan.find_composition('maybe').children)
      assert_empty plan.connections
    end

    def test_a_child_selected_with_a_sibling
      files = { 'models/compositions/pair.rb' => <<~RUBY }
        require 'models/devices/rover'
        using_task_library 'rig'
        module Rig
          module Compositions
            class Single < Syskit::Composition
              add Services::Pose, as: 'pose'
              add OroGen.rig.Follower, as: 'follower'
              pose_child.pose_port.connect_to follower_child.pose_port
            end
            class Pair < Syskit::Composition
              add OroGen.rig.Tracker, as: 'tracker'
              add(Single, as: 'single').use('pose' => tracker_child)
            end
          end
        end
      RUBY
      app = follow_app(<<~RUBY, files)
        require 'models/compositions/pair'
        profile 'Base' do
          define 'pair', Compositions::Pair
        end
      RUBY
      error = plan_error(app, 'pair_def')
      assert_match(/provides Rig::Services::Pose several times/, error.message)
    end

    def test_delayed_arguments_take_the_parent_composition_arguments
      files = { 'models/compositions/tuned.rb' => <<~RUBY }
        require 'models/devices/rover'
        using_task_library 'rig'
        module Rig
          module Compositions
            class Tuned < Syskit::Composition
              argument :gain
              add(OroGen.rig.Follower, as: 'follower').with_arguments(gain: from(:parent_task).gain)
            end
          end
        end
      RUBY
      app = follow_app(<<~RUBY, files)
        require 'models/compositions/tuned'
        profile 'Base' do
          define 'tuned', Compositions::Tuned.with_arguments(gain: 4.5)
          define 'untuned', Compositions::Tuned
        end
      RUBY
      result = Network::Generator.plan_profile(app, Rig::Profiles::Base.syskit_profile, actions: ['tuned_def'])
      follower = result.tasks.find { |t| t.model == OroGen.rig.Follower }
      assert_equal 4.5, follower.arguments[:gain]
      result = Network::Generator.plan_profile(app, Rig::Profiles::Base.syskit_profile, actions: ['untuned_def'])
      refute result.tasks.first.arguments.key?(:gain)
    end

    CONFD = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          class Confd < Syskit::Composition
            add OroGen.rig.Follower, as: 'follower'
            conf 'fast', follower_child => %w[default fast]
          end
        end
      end
    RUBY

    def test_composition_conf_selects_the_children_sections
      files = { 'models/compositions/confd.rb' => CONFD,
                'config/orogen/rig::Follower.yml' => "--- name:default\ngain: 1.5\n--- name:fast\ngain: 5.0\n" }
      app = follow_app(<<~RUBY, files)
        require 'models/compositions/confd'
        profile 'Base' do
          define 'slow', Compositions::Confd
          define 'fast', Compositions::Confd.with_conf('fast')
        end
      RUBY
      assert_equal 1.5, plan_of(app, 'slow_def').tasks.first.properties['gain']
      task = plan_of(app, 'fast_def').tasks.first
      assert_equal %w[default fast], task.conf
      assert_equal 5.0, task.properties['gain']
    end

    def test_a_driver_child_without_its_device
      files = { 'models/compositions/direct.rb' => <<~RUBY }
        require 'models/devices/rover'
        using_task_library 'rig'
        module Rig
          module Compositions
            class Direct < Syskit::Composition
              add OroGen.rig.WheelDriver, as: 'wheel'
            end
          end
        end
      RUBY
      app = follow_app(<<~RUBY, files)
        require 'models/compositions/direct'
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'direct', Compositions::Direct
          define 'direct_left', Compositions::Direct.use('wheel' => left_wheel_dev)
        end
      RUBY
      error = plan_error(app, 'direct_def')
      assert_match(/the child 'wheel' of Rig::Compositions::Direct \(direct.wheel\) is a rig::WheelDriver, /,
                   error.message)
      assert_match(/which drives a Rig::Devices::Wheel, but no device is selected for it/, error.message)
      assert_equal 'left_wheel', plan_of(app, 'direct_left_def').find_composition('direct_left').children['wheel']
    end

    def test_a_device_used_two_ways
      app = follow_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'a', Compositions::Follow.use('pose' => gps_dev, #{WHEELS})
          define 'b', Compositions::Follow.use('pose' => gps_dev.with_conf('default', 'rtk'), #{WHEELS})
        end
      RUBY
      error = plan_error(app, 'a_def', 'b_def')
      assert_match(/device 'gps' is used with sections default .* and with sections default, rtk, /, error.message)
      assert_match(/but its driver is one task/, error.message)
    end

    def test_the_comment_above_the_class_documents_it
      load_rig({ 'models/compositions/doc.rb' => <<~RUBY })
        module Rig
          # Watches the robot's pose
          # and logs it.
          class Documented < Syskit::Composition
          end
        end
      RUBY
      assert_equal "Watches the robot's pose\nand logs it.", Rig::Documented.doc
    end

    def test_reliable_inputs_get_a_buffer
      files = { 'models/compositions/reliable.rb' => <<~RUBY }
        require 'models/devices/rover'
        using_task_library 'rig'
        module Rig
          module Compositions
            class Reliable < Syskit::Composition
              add OroGen.rig.Splitter, as: 'split'
              add OroGen.rig.Logger, as: 'log'
              split_child.left_port.connect_to log_child.in_port
              split_child.right_port.connect_to log_child.in_port, type: :buffer, size: 50
            end
          end
        end
      RUBY
      orogen = FILES['models/orogen/rig.orogen'].sub('.multiplexes', '.multiplexes.needs_reliable_connection')
      app = follow_app(<<~RUBY, files.merge('models/orogen/rig.orogen' => orogen))
        require 'models/compositions/reliable'
        profile 'Base' do
          define 'reliable', Compositions::Reliable
        end
      RUBY
      policies = plan_of(app, 'reliable_def').connections.to_h { |c| [c.from.port, c.policy] }
      assert_equal({ 'type' => 'buffer', 'size' => 20 }, policies['left'])
      assert_equal({ 'type' => 'buffer', 'size' => 50 }, policies['right'])
    end

    # A misspelled child or port reader says what the composition has.
    def test_a_misspelled_port_is_explained
      assert_typo_explained 'follower_child.comand_port',
                            "Rig::Compositions::Follow.follower_child has no port 'comand' (did you mean 'command'?)",
                            'its ports: command, pose, state'
    end

    def test_a_misspelled_child_is_explained
      assert_typo_explained 'folower_child.command_port',
                            "Rig::Compositions::Follow has no child 'folower' (did you mean 'follower'?)",
                            'its children: pose, follower, split, left, right'
    end

    def assert_typo_explained(typo, message, hint)
      follow = FOLLOW.sub("export follower_child.command_port, as: 'speed'", "export #{typo}, as: 'speed'")
      root = rig_app({ 'models/compositions/follow.rb' => follow }, requires: ['models/compositions/follow'])
      error = load_problem(root)
      assert_reported error, /\A#{Regexp.escape(message)}\z/, at: 'models/compositions/follow.rb:16', root: root
      assert_equal hint, error.hint
    end
  end
end
