# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Profiles' definitions, tags, +use+ and +use_profile+, as Syskit's
  # profiles have them.
  class TestProfileDefinitions < Minitest::Test
    include CompositionTestHelper

    def watch_app(profile)
      load_rig({ 'models/compositions/watch.rb' => WATCH }, profile: profile, requires: ['models/compositions/watch'])
    end

    def test_define_gives_a_def_action
      app = watch_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          # Follows the GPS
          define 'watch', Compositions::Watch.use('pose' => gps_dev)
          define 'watch_fast', watch_def.with_arguments(rate: 10)
        end
      RUBY
      base = Rig::Profiles::Base
      definition = base.watch_def
      assert_kind_of InstanceRequirements, definition
      assert_equal 'Rig::Profiles::Base.watch_def', definition.to_s
      assert_same definition, base.syskit_profile.find_action('watch_def')
      assert_same definition, base.syskit_profile.find_action('watch')
      assert_equal({ rate: 10 }, base.watch_fast_def.arguments)
      assert_equal 'Follows the GPS', base.syskit_profile.definitions['watch'].doc
      assert_equal %w[gps_dev left_wheel_dev right_wheel_dev watch_def watch_fast_def],
                   base.syskit_profile.action_names
      assert_equal 'models/profiles/base.rb:14', definition.declared_at.to_s(app.root)
    end

    def test_a_definition_name_must_be_a_method_name
      root = rig_app({ 'models/compositions/watch.rb' => WATCH },
                     profile: <<~RUBY, requires: ['models/compositions/watch'])
                       profile 'Base' do
                         define 'Watch It', Compositions::Watch
                       end
                     RUBY
      error = load_problem(root)
      assert_match(/define expects a definition name, got "Watch It"/, error.message)
      assert_equal 'models/profiles/base.rb:7', error.location.to_s(root)
    end

    def test_define_refuses_what_is_not_a_model
      root = rig_app({}, profile: <<~RUBY)
        profile 'Base' do
          define 'watch', 'Compositions::Watch'
        end
      RUBY
      error = load_problem(root)
      assert_match(/define 'watch' expects a model, a device or requirements, got "Compositions::Watch"/, error.message)
    end

    def test_an_unknown_definition
      app = watch_app(<<~RUBY)
        profile 'Base' do
          define 'watch', Compositions::Watch
        end
      RUBY
      error = assert_raises(UnknownName) { plan_of(app, 'wach_def') }
      assert_match(/has no action 'wach_def' \(did you mean 'watch_def'\?\)/, error.message)
    end

    def test_profile_use_selects_for_every_definition
      app = watch_app(<<~RUBY)
        profile 'Base' do
          use Services::Pose => OroGen.rig.Tracker.front_pose_srv
          define 'watch', Compositions::Watch
        end
      RUBY
      assert_equal 'tracker', plan_of(app, 'watch_def').find_composition('watch').children['pose']
    end

    def test_tags_are_selected_by_the_profile_using_them
      app = watch_app(<<~RUBY)
        profile 'Generic' do
          tag 'localization', Services::Pose
          define 'watch', Compositions::Watch.use('pose' => localization_tag)
        end
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          use_profile Generic, 'localization' => gps_dev
        end
        profile 'Unselected' do
          use_profile Generic
        end
      RUBY
      assert_kind_of Actions::Profile::Tag, Rig::Profiles::Generic.localization_tag
      plan = plan_of(app, 'watch_def')
      assert_equal 'gps', plan.find_composition('watch').children['pose']
      error = assert_raises(NetworkError) do
        Network::Generator.plan_profile(app, Rig::Profiles::Unselected.syskit_profile, actions: ['watch_def'])
      end
      assert_match(/Rig::Profiles::Generic.localization_tag selects nothing/, error.message)
      assert_match(/use_profile Rig::Profiles::Generic, 'localization' => Model/, error.hint)
      assert_equal 'models/profiles/base.rb:20', error.location.to_s(app.root) # use_profile Generic
    end

    # As in Syskit, a profile may leave its own tags to the profiles using
    # it: `syskit check` checks its definitions there, not in it.
    def test_check_leaves_a_profile_s_own_tags_to_the_profiles_using_it
      root = rig_app({ 'models/compositions/watch.rb' => WATCH }, requires: ['models/compositions/watch'],
                                                                  profile: <<~RUBY)
                                                                    profile 'Generic' do
                                                                      tag 'localization', Services::Pose
                                                                      define 'watch', Compositions::Watch.use('pose' => localization_tag)
                                                                    end
                                                                    profile 'Base' do
                                                                      use_profile Generic
                                                                    end
                                                                  RUBY
      out, _, status = run_cli('check', '--app', root)
      assert_equal 1, status
      assert_equal 1, out.lines.grep(/^\S+:\d+: /).size, out
      assert_match(%r{^models/profiles/base.rb:11: .*Rig::Profiles::Generic.localization_tag selects nothing}, out)
    end

    def test_use_profile_brings_devices_and_definitions
      app = watch_app(<<~RUBY)
        profile 'Sensors' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'watch', Compositions::Watch.use('pose' => gps_dev)
        end
        profile 'Base' do
          use_profile Sensors
          define 'watch_tracker', Compositions::Watch.use('pose' => OroGen.rig.Tracker.rear_pose_srv)
        end
      RUBY
      base = Rig::Profiles::Base.syskit_profile
      assert_equal %w[gps_dev left_wheel_dev right_wheel_dev watch_def watch_tracker_def], base.action_names
      assert_equal 'Rig::Profiles::Base.watch_def', Rig::Profiles::Base.watch_def.to_s
      plan = plan_of(app, 'watch_def')
      assert_equal 'gps', plan.find_composition('watch').children['pose']
      assert_equal 'Rig::Profiles::Base.watch_def', plan.find_composition('watch').action
    end

    def test_use_profile_of_an_unknown_tag
      root = rig_app({ 'models/compositions/watch.rb' => WATCH },
                     profile: <<~RUBY, requires: ['models/compositions/watch'])
                       profile 'Generic' do
                         tag 'localization', Services::Pose
                       end
                       profile 'Base' do
                         use_profile Generic, 'localisation' => OroGen.rig.Tracker
                       end
                     RUBY
      error = load_problem(root)
      assert_match(/Rig::Profiles::Generic has no tag 'localisation' \(did you mean 'localization'\?\)/, error.message)
      assert_equal 'models/profiles/base.rb:10', error.location.to_s(root)
    end

    # As Syskit's use_profile: transform_names renames the definitions it
    # brings (a profile used twice, once per arm), each with its own tags.
    def test_use_profile_renames_definitions_with_transform_names
      app = watch_app(<<~RUBY)
        profile 'Side' do
          tag 'localization', Services::Pose
          define 'watch', Compositions::Watch.use('pose' => localization_tag)
        end
        profile 'Base' do
          use_profile Side, localization: OroGen.rig.Tracker.rear_pose_srv, transform_names: ->(name) { "rear_\#{name}" }
          use_profile Side, 'localization' => OroGen.rig.Tracker.front_pose_srv
        end
      RUBY
      assert_equal %w[rear_watch_def watch_def], Rig::Profiles::Base.syskit_profile.action_names
      assert_equal %w[rear_watch watch], [Rig::Profiles::Base.rear_watch_def.name, Rig::Profiles::Base.watch_def.name]
      assert_equal ['tracker.rear -> follower.pose'], connection_lines(plan_of(app, 'rear_watch_def'))
      assert_equal ['tracker.front -> follower.pose'], connection_lines(plan_of(app, 'watch_def'))
    end

    def test_transform_names_must_give_method_names
      root = rig_app({ 'models/compositions/watch.rb' => WATCH },
                     profile: <<~RUBY, requires: ['models/compositions/watch'])
                       profile 'Side' do
                         define 'watch', Compositions::Watch
                       end
                       profile 'Base' do
                         use_profile Side, transform_names: ->(name) { "rear \#{name}" }
                       end
                     RUBY
      error = load_problem(root)
      assert_match(/use_profile expects a definition name from transform_names, got "rear watch"/, error.message)
      assert_equal 'models/profiles/base.rb:10', error.location.to_s(root)
    end

    def test_planning_a_profile_plans_its_devices_and_definitions
      app = watch_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'watch', Compositions::Watch.use('pose' => gps_dev)
        end
      RUBY
      plan = plan_of(app)
      assert_equal %w[follower gps left_wheel right_wheel], plan.tasks.map(&:name)
      assert_equal %w[watch], plan.compositions.map(&:name)
    end
  end
end
