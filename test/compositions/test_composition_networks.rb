# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Networks of compositions: children instantiated through dependency
  # injection, tasks merged, connections made through services' port
  # mappings and exports, the plan keeping the hierarchy.
  class TestCompositionNetworks < Minitest::Test
    include CompositionTestHelper

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
      assert_equal ['follower', nil], [cmp.exports['speed'].task, cmp.parent]
      assert_equal ['follower.command -> splitter.in', 'gps.position -> follower.pose',
                    'splitter.left -> left_wheel.cmd', 'splitter.right -> right_wheel.cmd'], connection_lines(plan)
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
      assert_equal(['gps.position -> follower.pose'],
                   plan.connections.map { |c| "#{c.from.task}.#{c.from.port} -> #{c.to.task}.#{c.to.port}" })
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

    CASCADE = <<~RUBY
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

    def test_child_compositions_and_exports_through_them
      app = follow_app(<<~RUBY, 'models/compositions/cascade.rb' => CASCADE)
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

    # Sections a child cannot have are reported where they were chosen:
    # the composition's conf statement, the child's with_conf.
    def test_missing_sections_of_children_are_reported_where_they_are_chosen
      follow = FOLLOW.sub("export follower_child.command_port, as: 'speed'",
                          "export follower_child.command_port, as: 'speed'\n" \
                          "conf 'slow', follower_child => %w[default slow]\n" \
                          "split_child.with_conf('fast')")
      files = { 'models/compositions/follow.rb' => follow,
                'config/orogen/rig::Follower.yml' => "--- name:default\ngain: 1.0\n" }
      app = follow_app(<<~RUBY, files)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'slow', Compositions::Follow.use('pose' => gps_dev, #{WHEELS}).with_conf('slow')
        end
      RUBY
      errors = assert_raises(ErrorList) { plan_of(app, 'slow_def') }.errors
      assert_reported errors[0], /no section 'slow' in rig::Follower.yml/, at: 'models/compositions/follow.rb:17',
                                                                           root: app.root
      assert_equal "add '--- name:slow' to rig::Follower.yml", errors[0].hint # default is asked for too
      assert_reported errors[1], /rig::Splitter 'splitter' asks for sections fast but rig::Splitter has no conf/,
                      at: 'models/compositions/follow.rb:18', root: app.root
    end
  end
end
