# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # What a child overloaded in a submodel (+overload 'pose', Odometry+)
  # does to the declarations written against it: they follow the child,
  # its ports mapped through the services that replaced what it required.
  class TestChildOverloads < Minitest::Test
    include CompositionTestHelper::OnRig

    # A pose following composition, and a submodel of it in which the
    # pose child is overloaded with odometry.
    def overloaded_pose_child
      parent = new_cmp do
        add Rig::Services::Pose, as: 'pose'
        add OroGen.rig.Follower, as: 'follow'
        pose_child.pose_port.connect_to follow_child.pose_port
        export pose_child.pose_port, as: 'out'
      end
      model = parent.new_submodel
      model.overload 'pose', Rig::Services::Odometry
      [parent, model]
    end

    # A parent's exports and connections are seen from a submodel through
    # the child as the submodel overloads it, the service's ports mapped.
    def test_exports_follow_an_overload_in_a_submodel
      parent, model = overloaded_pose_child
      assert_equal model.pose_child.odometry_port, model.find_exported_output('out')
      assert_same parent.pose_child, parent.find_exported_output('out').child, 'the parent is left as it is'
    end

    # A model's exports are kept between generations: an overload declared
    # after they were read still shows.
    def test_exports_read_before_an_overload_follow_it
      parent, = overloaded_pose_child
      model = parent.new_submodel
      assert_equal model.pose_child.pose_port, model.find_exported_output('out')
      model.overload 'pose', Rig::Services::Odometry
      assert_equal model.pose_child.odometry_port, model.find_exported_output('out')
    end

    def test_connections_follow_an_overload_in_a_submodel
      parent, model = overloaded_pose_child
      assert_same model.pose_child, model.port_connections.first.from.child
      assert model.pose_child.odometry_port.connected_to?(model.follow_child.pose_port)
      assert_same parent.pose_child, parent.port_connections.first.from.child
    end

    # As Syskit's overload_info: the overloaded child, and which ports of
    # the new requirements stand for its ports.
    def test_an_overloaded_child_knows_the_child_it_overloads
      parent, model = overloaded_pose_child
      assert_same parent.pose_child, model.pose_child.overload_info.required
      assert_equal({ 'pose' => 'odometry' }, model.pose_child.port_mappings)
      tracked = parent.new_submodel
      tracked.overload 'pose', OroGen.rig.GPSDriver
      assert_same parent.pose_child, tracked.pose_child.overload_info.required
      assert_equal OroGen.rig.GPSDriver.gps_srv, tracked.pose_child.overload_info.selected.service
      assert_nil parent.pose_child.parent_model
    end

    # The child keeps the ports of what it was required as, mapped onto
    # the model that replaced it.
    def test_an_overloaded_child_keeps_the_ports_of_the_services_it_was
      model = new_cmp { add Rig::Services::Pose, as: 'pose' }
      model.overload 'pose', Rig::Services::Odometry
      assert_equal [Rig::Services::Odometry], model.pose_child.models
      assert_equal [Rig::Services::Pose], model.pose_child.facets
      assert_equal %w[odometry pose], model.pose_child.ports.keys.sort
      assert_equal model.pose_child.odometry_port, model.pose_child.pose_port
      assert_equal [Rig::Services::Pose], model.new_submodel.pose_child.facets
    end
  end
end
