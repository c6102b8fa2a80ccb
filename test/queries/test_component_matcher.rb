# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'syskit/test/plan'

module Syskit
  module Queries
    # Model.match: the tasks of a plan (held as data) that fullfill
    # models, and the +_srv+ / +_port+ readers that narrow to their
    # services and ports.
    class TestComponentMatcher < Minitest::Test
      include CompositionTestHelper

      def setup
        super
        load_rig
        @plan = Test::Plan.new
        @tracker = @plan.add(OroGen.rig.Tracker.new)
        @splitter = @plan.add(OroGen.rig.Splitter.new)
      end

      def test_a_task_model_finds_its_tasks_only
        assert_equal [@tracker], OroGen.rig.Tracker.match.to_a(@plan)
        assert_equal [@splitter].to_set, OroGen.rig.Splitter.match.to_set(@plan)
      end

      def test_all_models_given_must_be_fullfilled
        matcher = ComponentMatcher.new.with_model([OroGen.rig.Tracker, Rig::Services::Pose])
        assert_equal [@tracker], matcher.to_a(@plan)
        matcher = ComponentMatcher.new.with_model([OroGen.rig.Splitter, Rig::Services::Pose])
        assert_empty matcher.to_a(@plan)
      end

      def test_abstract_narrows_to_the_tasks_marked_abstract
        other = @plan.add(OroGen.rig.Tracker.new)
        other.abstract = true
        assert_equal [other], OroGen.rig.Tracker.match.abstract.to_a(@plan)
        assert_equal [@tracker], OroGen.rig.Tracker.match.not_abstract.to_a(@plan)
      end

      def test_the_srv_reader_finds_the_service_on_the_tasks
        assert_equal [@tracker.rear_pose_srv], OroGen.rig.Tracker.match.rear_pose_srv.to_a(@plan)
      end

      def test_the_port_reader_finds_the_port_on_the_tasks
        assert_equal [@splitter.left_port], OroGen.rig.Splitter.match.left_port.to_a(@plan)
      end

      def test_a_name_no_model_has_is_no_method
        error = assert_raises(NoMethodError) { OroGen.rig.Splitter.match.middle_port }
        assert_equal :middle_port, error.name
        assert_raises(NoMethodError) { OroGen.rig.Splitter.match.front_pose_srv }
      end

      def test_a_port_name_several_models_have_is_ambiguous
        matcher = ComponentMatcher.new.with_model([OroGen.rig.Follower, Rig::Services::Pose])
        error = assert_raises(Ambiguous) { matcher.pose_port }
        assert_match(/more than one port named 'pose'/, error.message)
      end
    end
  end
end
