# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'json'

module Syskit
  # Compositions and definitions through bin/syskit: plan, check, the
  # plan's formats.
  class TestCompositionCLI < Minitest::Test
    include CompositionTestHelper

    PROFILE = <<~RUBY
      profile 'Base' do
        robot do
          device Devices::GPS, as: 'gps'
        end
        define 'watch', Compositions::Watch.use('pose' => gps_dev)
        define 'watch_tracker', Compositions::Watch.use('pose' => OroGen.rig.Tracker.front_pose_srv)
        define 'unselected', Compositions::Watch
      end
    RUBY

    def app
      @app ||= rig_app({ 'models/compositions/watch.rb' => WATCH }, profile: PROFILE,
                                                                    requires: ['models/compositions/watch'])
    end

    def test_plan_of_a_definition_in_json
      out, err, status = run_cli('plan', '--app', app, 'Base', 'watch_def', '--format', 'json')
      assert_equal 0, status, err
      doc = JSON.parse(out)
      assert_equal [{ 'name' => 'watch', 'model' => 'Rig::Compositions::Watch',
                      'action' => 'Rig::Profiles::Base.watch_def', 'arguments' => {}, 'conf' => ['default'],
                      'children' => { 'pose' => 'gps', 'follower' => 'follower' },
                      'exports' => { 'speed' => { 'task' => 'follower', 'port' => 'command' } }, 'parent' => nil }],
                   doc['compositions']
      assert_equal [{ 'from' => { 'task' => 'gps', 'port' => 'position' },
                      'to' => { 'task' => 'follower', 'port' => 'pose' },
                      'type' => RBS, 'policy' => { 'type' => 'data' } }], doc['connections']
    end

    def test_plan_of_the_whole_profile_says_which_definition_to_plan
      _, err, status = run_cli('plan', '--app', app, 'Base')
      assert_equal 1, status
      assert_match(%r{^models/profiles/base.rb:12: the child 'pose' of Rig::Compositions::Watch \(unselected.pose\)},
                   err)
      assert_match(/warning: the 3 definitions of Rig::Profiles::Base were planned together, with its devices/, err)
      assert_match(/plan one at a time: syskit plan Rig::Profiles::Base watch_def/, err)
    end

    # Two definitions that need the one follower differently are
    # alternatives: the whole profile prints its devices' plan.
    def test_plan_of_a_profile_whose_definitions_are_alternatives_is_the_devices_plan
      profile = <<~RUBY
        profile 'Base' do
          robot do
            device Devices::GPS, as: 'gps'
          end
          define 'watch', Compositions::Watch.use('pose' => gps_dev)
          define 'watch_slowly', watch_def.use('follower' => OroGen.rig.Follower.with_conf('slow'))
        end
      RUBY
      app = rig_app({ 'models/compositions/watch.rb' => WATCH,
                      'config/orogen/rig::Follower.yml' => "--- name:default\n--- name:slow\n" },
                    profile: profile, requires: ['models/compositions/watch'])
      out, err, status = run_cli('plan', '--app', app, 'Base', '--format', 'json')
      assert_equal 0, status, err
      doc = JSON.parse(out)
      assert_equal(%w[gps], doc['tasks'].map { |t| t['name'] })
      assert_empty doc['compositions']
      assert_match(%r{^models/profiles/base.rb:\d+: warning: the 2 definitions of Rig::Profiles::Base }, err)
      assert_match(/cannot all run at once: /, err)
      assert_match(/1 problem when planned together \(the first: .*follower/, err)
      assert_match(/hint: plan one definition at a time: syskit plan Rig::Profiles::Base watch_def /, err)
      assert_match(/\(its definitions: watch_def, watch_slowly_def\)/, err)

      out, err, status = run_cli('plan', '--app', app, 'Base', 'watch_slowly_def')
      assert_equal 0, status, err
      assert_match(/follower  rig::Follower  \(deployment follower, conf slow\)/, out)
    end

    def test_plan_of_a_generic_profile_is_the_devices_plan
      profile = <<~RUBY
        profile 'Base' do
          tag 'pose', Services::Pose
          robot do
            device Devices::GPS, as: 'gps'
          end
          define 'watch', Compositions::Watch.use('pose' => pose_tag)
        end
      RUBY
      app = rig_app({ 'models/compositions/watch.rb' => WATCH }, profile: profile,
                                                                 requires: ['models/compositions/watch'])
      out, err, status = run_cli('plan', '--app', app, 'Base')
      assert_equal 0, status, err
      assert_match(/^Tasks \(1\)\n  gps  /, out)
      assert_match(/warning: Rig::Profiles::Base leaves what its tags stand for to the profiles using it \(the first: /,
                   err)
      assert_match(/hint: plan a profile that selects them, or one definition: /, err)
    end

    def test_check_generates_each_definition_on_its_own
      out, _, status = run_cli('check', '--app', app)
      assert_equal 1, status
      errors = out.lines.grep(/^\S+:\d+: /)
      assert_equal 1, errors.size, out
      assert_match(%r{\Amodels/profiles/base.rb:12: the child 'pose' of Rig::Compositions::Watch \(unselected.pose\) },
                   errors.first)
      assert_match(/needs a Rig::Services::Pose/, errors.first)
      assert_match(/^Rig: 1 error\(s\)/, out)
    end

    def test_text_and_dot_show_the_compositions
      out, = run_cli('plan', '--app', app, 'Base', 'watch_def')
      assert_includes out, <<~TEXT
        Compositions (1)
          watch  Rig::Compositions::Watch  (Rig::Profiles::Base.watch_def, conf default)
            pose      gps
            follower  follower
            exports   speed -> follower.command
      TEXT
      dot, = run_cli('plan', '--app', app, 'Base', 'watch_def', '--format', 'dot')
      assert_match(/subgraph "cluster_composition_watch" \{\n    label="watch\\nRig::Compositions::Watch";/, dot)
      assert_match(/^    "follower" \[label=/, dot)
    end
  end
end
