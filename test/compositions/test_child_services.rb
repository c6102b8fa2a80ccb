# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # A composition child seen through its services, as generators in real
  # bundles walk them (rock_auv's control cascades).
  class TestChildServices < Minitest::Test
    include CompositionTestHelper::OnRig

    # The services of a child, as generators in real bundles walk them:
    # each a view of the child through one service of its model, whose
    # ports are the child's behind it.
    def test_the_services_of_a_child
      model = new_cmp do
        add OroGen.rig.Tracker, as: 'track'
        add OroGen.rig.Follower, as: 'follow'
      end
      front, rear = model.track_child.find_all_data_services_from_type(Rig::Services::Pose)
      assert_equal %w[front_pose rear_pose], [front.name, rear.name]
      assert_same Rig::Services::Pose, rear.model.model
      assert_equal rear, model.track_child.find_data_service('rear_pose')
      refute_equal front, rear
      assert_equal rear, rear.as_real_model
      assert_raises(ArgumentError) { rear.as(Rig::Services::Odometry) }
    end

    def test_a_child_s_service_connects_its_own_ports
      model = new_cmp do
        add OroGen.rig.Tracker, as: 'track'
        add OroGen.rig.Follower, as: 'follow'
      end
      model.track_child.rear_pose_srv.connect_to model.follow_child
      assert model.track_child.rear_port.connected_to?(model.follow_child.pose_port)
      refute model.track_child.front_port.connected_to?(model.follow_child.pose_port)
    end

    def test_a_port_connects_to_a_child_s_service
      model = new_cmp do
        add OroGen.rig.Splitter, as: 'split'
        add Rig::Devices::Wheel, as: 'wheel'
      end
      command, = model.wheel_child.find_all_data_services_from_type(Rig::Services::SpeedCommand)
      model.split_child.left_port.connect_to command
      assert model.split_child.left_port.connected_to?(model.wheel_child.cmd_port)
    end

    def test_the_services_of_a_child_that_requires_a_service
      model = new_cmp { add Rig::Services::Odometry, as: 'odom' }
      pose, = model.odom_child.find_all_data_services_from_type(Rig::Services::Pose)
      assert_same Rig::Services::Odometry, pose.as_real_model.service_model
      assert_equal model.odom_child.odometry_port, pose.pose_port, 'the same port of the child'
    end
  end
end
