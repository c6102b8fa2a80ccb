# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # A composition child added with selections of its own
  # (+add(Cmp.use(...), as: 'x')+) is the specialization they select, as
  # in Syskit: it has that specialization's ports, which the parent
  # connects.
  class TestChildSpecializations < Minitest::Test
    include CompositionTestHelper

    # Watches a pose; with a tracker, exports its rear pose too.
    WATCH = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          class Watch < Syskit::Composition
            add Services::Pose, as: 'pose'
            add(OroGen.rig.Follower, as: 'follower').prefer_deployed_tasks('follower')
            pose_child.pose_port.connect_to follower_child.pose_port
            specialize pose_child => OroGen.rig.Tracker do
              export pose_child.rear_port
            end
          end
        end
      end
    RUBY

    # Logs the speed the follower of a tracker-fed Watch commands.
    TRACKED = <<~RUBY
      require 'models/compositions/watch'
      module Rig
        module Compositions
          class Tracked < Syskit::Composition
            add(Watch, as: 'watch').use('pose' => OroGen.rig.Tracker.front_pose_srv)
            add(OroGen.rig.Follower, as: 'rear_follower').prefer_deployed_tasks('rear_follower')
            watch_child.rear_port.connect_to rear_follower_child.pose_port
          end
        end
      end
    RUBY

    def tracked_app(profile)
      robot = "#{FILES['config/robots/default.rb']}Syskit.conf.use_deployment OroGen.rig.Follower => 'rear_follower'\n"
      load_rig({ 'models/compositions/watch.rb' => WATCH, 'models/compositions/tracked.rb' => TRACKED,
                 'config/robots/default.rb' => robot },
               profile: profile, requires: ['models/compositions/tracked'])
    end

    def test_the_child_has_the_ports_of_the_specialization_its_selections_select
      tracked_app("profile 'Base' do\nend\n")
      child = Rig::Compositions::Tracked.watch_child
      assert_equal %w[rear], child.ports.keys
      assert child.rear_port.connected_to?(Rig::Compositions::Tracked.rear_follower_child.pose_port)
      assert_equal [], Rig::Compositions::Watch.ports.keys
    end

    def test_the_plan_connects_the_specialization_export
      app = tracked_app("profile 'Base' do\n  define 'tracked', Compositions::Tracked\nend\n")
      plan = plan_of(app, 'tracked_def')
      assert_equal 'Rig::Compositions::Watch/pose.is_a?(rig::Tracker)', plan.find_composition('tracked.watch').model
      assert_includes connection_lines(plan), 'tracker.rear -> rear_follower.pose'
    end

    def test_a_selection_making_another_specialization_is_reported_at_the_connection
      app = tracked_app(<<~RUBY)
        profile 'Base' do
        #{ROBOT.lines.map { |l| "  #{l}" }.join}
          define 'tracked', Compositions::Tracked.use('watch' => Compositions::Watch.use('pose' => gps_dev))
        end
      RUBY
      error = plan_error(app, 'tracked_def')
      assert_reported error, /Rig::Compositions::Watch 'tracked.watch' has no output port 'rear'/,
                      at: 'models/compositions/tracked.rb:7', root: app.root
    end
  end
end
