# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Requirements as Syskit's InstanceRequirements read and change: their
  # services and children (x_srv, x_child) and the statements that say
  # what is asked of them.
  class TestInstanceRequirements < Minitest::Test
    include CompositionTestHelper

    def tracker_app
      load_rig({ 'models/compositions/watch.rb' => WATCH }, profile: <<~RUBY, requires: ['models/compositions/watch'])
        profile 'Base' do
          define 'tracker', OroGen.rig.Tracker.with_arguments(rate: 5)
          define 'watch', Compositions::Watch.use('pose' => tracker_def.rear_pose_srv)
        end
      RUBY
    end

    def test_a_service_of_requirements_keeps_what_they_ask
      app = tracker_app
      rear = Rig::Profiles::Base.tracker_def.rear_pose_srv
      assert_same OroGen.rig.Tracker.rear_pose_srv, rear.service
      assert_equal({ rate: 5 }, rear.arguments)
      assert_equal 'Rig::Profiles::Base.tracker_def.rear_pose_srv', rear.to_s
      assert_same rear.service, OroGen.rig.Tracker.with_conf('fast').find_data_service('rear_pose').service
      assert_nil OroGen.rig.Tracker.with_conf('fast').find_data_service('side')
      assert_equal ['tracker.rear -> follower.pose'], connection_lines(plan_of(app, 'watch_def'))
    end

    def test_the_children_of_requirements
      tracker_app
      assert_same Rig::Compositions::Watch.pose_child, Rig::Profiles::Base.watch_def.pose_child
      refute_respond_to Rig::Profiles::Base.tracker_def, :pose_child
    end

    def test_a_service_by_its_model
      tracker_app
      follower = OroGen.rig.Follower.with_arguments(gain: 2)
      assert_nil follower.find_data_service_from_type(Rig::Services::Pose)
      rear = Rig::Profiles::Base.tracker_def.rear_pose_srv
      assert_same rear, rear.find_data_service_from_type(Rig::Services::Pose)
      error = assert_raises(AmbiguousServiceSelection) do
        Rig::Profiles::Base.tracker_def.find_data_service_from_type(Rig::Services::Pose)
      end
      assert_match(/several services of type Rig::Services::Pose: front_pose, rear_pose/, error.message)
      assert_equal File.expand_path(__FILE__), error.location.path
    end

    def test_a_misspelled_service_is_explained
      root = rig_app({ 'models/compositions/watch.rb' => WATCH },
                     profile: <<~RUBY, requires: ['models/compositions/watch'])
                       profile 'Base' do
                         define 'watch', Compositions::Watch.use('pose' => OroGen.rig.Tracker.with_arguments(rate: 5).rer_pose_srv)
                       end
                     RUBY
      error = load_problem(root)
      assert_match(/rig::Tracker.with_arguments\(rate: 5\) has no service 'rer_pose' \(did you mean 'rear_pose'\?\)/,
                   error.message)
      assert_equal 'its services: front_pose, rear_pose', error.hint
      assert_equal 'models/profiles/base.rb:7', error.location.to_s(root)
    end

    def test_statements_on_arguments_sections_and_services
      tracker_app
      follower = OroGen.rig.Follower.with_arguments(gain: 2.0)
      assert_empty follower.with_no_arguments.arguments
      assert_equal %w[fast], follower.use_conf('fast').conf
      rear = OroGen.rig.Tracker.with_conf('fast').select_service(OroGen.rig.Tracker.rear_pose_srv)
      assert_same OroGen.rig.Tracker.rear_pose_srv, rear.service
      assert_equal %w[fast], rear.conf
      assert_syskit_error(/service 'rear_pose' \(Rig::Services::Pose\) of rig::Tracker is not a service of/) do
        follower.select_service(OroGen.rig.Tracker.rear_pose_srv)
      end
    end

    # Syskit's deployment groups choose deployments at runtime, for a
    # profile or requirements: a located warning each, the deployments
    # come from config/robots.
    def test_deployment_groups_are_not_modelled
      app = load_rig({ 'models/compositions/watch.rb' => WATCH },
                     profile: <<~RUBY, requires: ['models/compositions/watch'])
                       profile 'Base' do
                         use_deployment OroGen.rig.Tracker => 'other_tracker'
                         define_deployment_group 'trackers' do
                           use_deployment OroGen.rig.Tracker => 'other_tracker'
                         end
                         use_group trackers_deployment_group
                         define 'tracker', OroGen.rig.Tracker.use_deployment(OroGen.rig.Tracker => 'other_tracker')
                       end
                     RUBY
      warnings = app.problems.map { |p| "#{p.location.to_s(app.root)}: #{p.message.sub(/: not modelled.*/, '')}" }
      assert_equal ['models/profiles/base.rb:7: use_deployment in profile Rig::Profiles::Base',
                    'models/profiles/base.rb:8: define_deployment_group in profile Rig::Profiles::Base',
                    'models/profiles/base.rb:11: use_group in profile Rig::Profiles::Base',
                    'models/profiles/base.rb:12: use_deployment on rig::Tracker (deployment groups)'], warnings
      assert_equal %w[tracker], plan_of(app, 'tracker_def').tasks.map(&:name)
    end

    # As Syskit's requirements: marked abstract on request, equal when they
    # ask for the same thing, their model a placeholder when they name
    # services only; a service found by type is ambiguous when a required
    # service model provides it too.
    def test_requirements_made_in_ruby
      pose = DataService.new_submodel(name: 'Pose')
      task = Component.new_submodel { provides pose, as: 'fix' }
      assert task.to_instance_requirements.abstract.abstract?
      refute task.to_instance_requirements.abstract?
      assert_equal InstanceRequirements.new([task]), task.to_instance_requirements
      refute_equal task.to_instance_requirements, task.with_arguments(x: 1)
      assert_equal pose.placeholder_model, pose.to_instance_requirements.model
      assert_same task, InstanceRequirements.new([task]).model
      assert_equal task.fix_srv, task.new.fix_srv.model
    end

    def test_a_service_both_required_and_provided_is_ambiguous
      pose = DataService.new_submodel(name: 'Pose')
      odometry = DataService.new_submodel(name: 'Odometry') { provides pose }
      task = Component.new_submodel { provides pose, as: 'fix' }
      assert_equal [], InstanceRequirements.new.models
      assert_raises(AmbiguousServiceSelection) do
        InstanceRequirements.new([task, odometry]).find_data_service_from_type(pose)
      end
    end
  end
end
