# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'syskit/test/plan'

module Syskit
  module Queries
    # Srv.match and Task.srv_srv.match: the services of the tasks of a
    # plan, each seen as the matched service model, and their ports.
    class TestDataServiceMatcher < Minitest::Test
      include CompositionTestHelper

      def setup
        super
        load_rig
        @plan = Test::Plan.new
        @tracker = @plan.add(OroGen.rig.Tracker.new)
        @plan.add(OroGen.rig.Splitter.new)
      end

      def test_a_service_model_finds_every_service_of_that_model
        assert_equal [@tracker.front_pose_srv, @tracker.rear_pose_srv].to_set,
                     Rig::Services::Pose.match.to_set(@plan)
      end

      def test_a_task_model_service_finds_that_service_only
        matcher = OroGen.rig.Tracker.front_pose_srv.match
        assert_equal Rig::Services::Pose, matcher.data_service_model
        assert_equal [@tracker.front_pose_srv], matcher.to_a(@plan)
      end

      def test_its_port_reader_gives_the_service_ports_behind_which_are_the_task_ports
        ports = OroGen.rig.Tracker.rear_pose_srv.match.pose_port.to_a(@plan)
        assert_equal [@tracker.rear_pose_srv.pose_port], ports
        assert_equal @tracker.rear_pose_srv, ports.first.component
        assert_equal @tracker.rear_port, ports.first.to_component_port
      end

      def test_task_predicates_narrow_the_tasks
        matcher = Rig::Services::Pose.match.abstract
        assert_empty matcher.to_a(@plan)
        @tracker.abstract = true
        assert_equal 2, matcher.to_a(@plan).size
      end

      def test_as_sees_the_services_as_a_model_they_provide
        matcher = Rig::Services::Odometry.match.as(Rig::Services::Pose)
        assert_equal Rig::Services::Pose, matcher.data_service_model
        error = assert_raises(ArgumentError) { matcher.as(Rig::Services::Odometry) }
        assert_equal 'cannot refine match from Rig::Services::Pose to Rig::Services::Odometry', error.message
      end
    end
  end
end
