# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Networks of compositions: children instantiated through dependency
  # injection, tasks merged, connections made through services' port
  # mappings and exports, the plan keeping the hierarchy.
  class TestCompositionNetworks < Minitest::Test
    include CompositionTestHelper

    # Follows the pose of a GPS (or any pose source), driving two wheels.
    FOLLOW = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          class Follow < Syskit::Composition
            argument :gain, default: 2.0
            add Services::Pose, as: 'pose'
            add OroGen.rig.Follower, as: 'follower'
            add OroGen.rig.Splitter, as: 'split'
            add Devices::Wheel, as: 'left'
            add Devices::Wheel, as: 'right'
            pose_child.pose_port.connect_to follower_child.pose_port
            follower_child.command_port.connect_to split_child.in_port
            split_child.left_port.connect_to left_child.cmd_port
            split_child.right_port.connect_to right_child.cmd_port
            export follower_child.command_port, as: 'speed'
          end
        end
      end
    RUBY

    def follow_app(profile, files = {})
      load_rig({ 'models/compositions/follow.rb' => FOLLOW }.merge(files),
               profile: profile, requires: ['models/compositions/follow'])
    end

    WHEELS = "'left' => left_wheel_dev, 'right' => right_wheel_dev"

    def test_a_definition_plans_its_composition_and_children
      app = follow_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'follow', Compositions::Follow.use('pose' => gps_dev, #{WHEELS})
        end
      RUBY
      plan = plan_of(app, 'follow_def')
      cmp = plan.find_composition('follow')
      assert_equal 'Rig::Compositions::Follow', cmp.model
      assert_equal 'Rig::Profiles::Base.follow_def', cmp.action
      assert_equal({ 'pose' => 'gps', 'follower' => 'follower', 'split' => 'splitter',
                     'left' => 'left_wheel', 'right' => 'right_wheel' }, cmp.children)
      assert_equal({ 'gain' => 2.0 }, cmp.arguments)
      assert_equal 'follower', cmp.exports['speed'].task
      assert_nil cmp.parent
      connections = plan.connections.map { |c| "#{c.from.task}.#{c.from.port} -> #{c.to.task}.#{c.to.port}" }
      assert_equal ['follower.command -> splitter.in', 'gps.position -> follower.pose',
                    'splitter.left -> left_wheel.cmd', 'splitter.right -> right_wheel.cmd'], connections
      assert_equal %w[follower gps left_wheel right_wheel splitter], plan.tasks.map(&:name)
    end

    def test_the_robot_selects_its_only_device_of_a_model
      app = follow_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'follow', Compositions::Follow.use(#{WHEELS})
          define 'by_gps_model', Compositions::Follow.use(Devices::GPS => gps_dev, #{WHEELS})
          define 'with_gps', Compositions::Follow.use(gps_dev, #{WHEELS})
        end
      RUBY
      error = plan_error(app, 'follow_def')
      assert_match(/the child 'pose' of Rig::Compositions::Follow \(follow.pose\) needs a Rig::Services::Pose/,
                   error.message)
      assert_equal 'models/profiles/base.rb:13', error.location.to_s(app.root)
      assert_match(/Rig::Compositions::Follow.use\('pose' => Model\)/, error.hint)
      # A selection by model applies to children requiring that model; a
      # default to every model the selected component fullfills.
      assert_match(/needs a Rig::Services::Pose/, plan_error(app, 'by_gps_model_def').message)
      plan = plan_of(app, 'with_gps_def')
      assert_equal 'gps', plan.find_composition('with_gps').children['pose']
    end

    def test_a_child_requiring_the_device_model_gets_the_single_device
      cmp = <<~RUBY
        module Rig
          module Compositions
            class Watch < Syskit::Composition
              add Devices::GPS, as: 'gps'
              add OroGen.rig.Follower, as: 'follower'
              gps_child.position_port.connect_to follower_child.pose_port
            end
          end
        end
      RUBY
      app = follow_app(<<~RUBY, 'models/compositions/watch.rb' => "require 'models/devices/rover'\n#{cmp}")
        require 'models/compositions/watch'
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'watch', Compositions::Watch
        end
      RUBY
      plan = plan_of(app, 'watch_def')
      assert_equal 'gps', plan.find_composition('watch').children['gps']
      assert_equal ['gps.position -> follower.pose'],
                   plan.connections.map { |c| "#{c.from.task}.#{c.from.port} -> #{c.to.task}.#{c.to.port}" }
    end

    def test_selecting_something_that_does_not_fullfill_the_child
      app = follow_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'follow', Compositions::Follow.use('pose' => OroGen.rig.Splitter, #{WHEELS})
        end
      RUBY
      error = plan_error(app, 'follow_def')
      assert_match(/rig::Splitter is selected for Rig::Compositions::Follow.pose_child, but it does not fullfill Rig::Services::Pose/,
                   error.message)
      assert_equal 'models/profiles/base.rb:13', error.location.to_s(app.root)
    end

    def test_selection_by_service_and_by_default
      app = follow_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'by_service', Compositions::Follow.use(Services::Pose => OroGen.rig.Tracker.rear_pose_srv, #{WHEELS})
          define 'by_default', Compositions::Follow.use(OroGen.rig.Tracker.front_pose_srv, #{WHEELS})
          define 'ambiguous', Compositions::Follow.use('pose' => OroGen.rig.Tracker, #{WHEELS})
        end
      RUBY
      assert_includes connection_lines(plan_of(app, 'by_service_def')), 'tracker.rear -> follower.pose'
      assert_includes connection_lines(plan_of(app, 'by_default_def')), 'tracker.front -> follower.pose'
      error = plan_error(app, 'ambiguous_def')
      assert_match(/it provides Rig::Services::Pose several times \(front_pose, rear_pose\)/, error.message)
      assert_match(/'pose' => OroGen.rig.Tracker.front_pose_srv/, error.hint)
    end

    def connection_lines(plan)
      plan.connections.map { |c| "#{c.from.task}.#{c.from.port} -> #{c.to.task}.#{c.to.port}" }
    end

    def test_one_driver_task_per_device_and_equal_tasks_merge
      app = follow_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'a', Compositions::Follow.use('pose' => gps_dev, #{WHEELS})
          define 'b', Compositions::Follow.use('pose' => gps_dev, #{WHEELS}).with_arguments(gain: 3.0)
        end
      RUBY
      plan = plan_of(app, 'a_def', 'b_def')
      assert_equal %w[follower gps left_wheel right_wheel splitter], plan.tasks.map(&:name)
      assert_equal 4, plan.connections.size
      assert_equal plan.find_composition('a').children, plan.find_composition('b').children
    end

    def test_tasks_reading_different_sources_stay_apart
      app = follow_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'a', Compositions::Follow.use('pose' => gps_dev, #{WHEELS})
          define 'b', Compositions::Follow.use('pose' => OroGen.rig.Tracker.front_pose_srv, #{WHEELS})
        end
      RUBY
      error = plan_error(app, 'a_def', 'b_def')
      assert_match(/\Aa.follower and b.follower both need the deployed task follower/, error.message)
      assert_equal 'models/profiles/base.rb:14', error.location.to_s(app.root)
      assert_match(/use_deployment OroGen.rig.Follower => 'b_follower'.*use\('follower' => /, error.hint)
    end

    def test_child_compositions_and_exports_through_them
      files = { 'models/compositions/cascade.rb' => <<~RUBY }
        require 'models/compositions/follow'
        module Rig
          module Compositions
            class Cascade < Syskit::Composition
              add Follow, as: 'follow'
              add OroGen.rig.Logger, as: 'log'
              follow_child.speed_port.connect_to log_child.in_port
            end
          end
        end
      RUBY
      app = follow_app(<<~RUBY, files)
        require 'models/compositions/cascade'
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'cascade', Compositions::Cascade.use('follow.pose' => gps_dev, 'follow.left' => left_wheel_dev,
                                                      'follow.right' => right_wheel_dev)
        end
      RUBY
      plan = plan_of(app, 'cascade_def')
      assert_equal %w[cascade cascade.follow], plan.compositions.map(&:name)
      assert_equal 'cascade.follow', plan.find_composition('cascade').children['follow']
      assert_equal 'cascade', plan.find_composition('cascade.follow').parent
      assert_includes connection_lines(plan), 'follower.command -> logger.in'
      text = Render::Text.render(plan)
      assert_match(/^  cascade  Rig::Compositions::Cascade  \(Rig::Profiles::Base.cascade_def, conf default\)$/, text)
      assert_match(/^    cascade.follow  Rig::Compositions::Follow  \(conf default\)$/, text)
    end

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

    def test_composition_conf_selects_the_children_sections
      files = {
        'models/compositions/confd.rb' => <<~RUBY,
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
        'config/orogen/rig::Follower.yml' => "--- name:default\ngain: 1.5\n--- name:fast\ngain: 5.0\n"
      }
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
      assert_match(/the child 'wheel' of Rig::Compositions::Direct \(direct.wheel\) is a rig::WheelDriver, which drives a Rig::Devices::Wheel, but no device is selected for it/,
                   error.message)
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
      assert_match(/device 'gps' is used with sections default .* and with sections default, rtk, but its driver is one task/,
                   error.message)
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
      orogen = FILES['models/orogen/rig.orogen'].sub("input_port('in', '/double').multiplexes",
                                                      "input_port('in', '/double').multiplexes.needs_reliable_connection")
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
  end
end
