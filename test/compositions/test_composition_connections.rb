# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # A composition model's connections as Syskit's tests read them: by
  # pair of child names, the connected port names and their policy.
  class TestCompositionConnections < Minitest::Test
    include CompositionTestHelper::OnRig

    def test_connections_by_child_pair_as_syskit_lists_them
      model = new_cmp do
        add OroGen.rig.Follower, as: 'follow'
        add OroGen.rig.Splitter, as: 'split'
        add Rig::Services::Pose, as: 'pose'
        follow_child.command_port.connect_to split_child.in_port, type: :buffer, size: 2
        pose_child.pose_port.connect_to follow_child.pose_port
      end
      expected = { %w[follow split] => { %w[command in] => { type: :buffer, size: 2 } },
                   %w[pose follow] => { %w[pose pose] => {} } }
      assert_equal expected, model.connections
      assert_equal expected.to_a, model.each_explicit_connection.to_a
      assert_equal 2, model.port_connections.size
    end

    def test_connections_name_the_ports_a_submodel_overloads_a_child_with
      parent = new_cmp do
        add Rig::Services::Pose, as: 'pose'
        add OroGen.rig.Follower, as: 'follow'
        pose_child.pose_port.connect_to follow_child.pose_port
      end
      submodel = parent.new_submodel
      submodel.overload 'pose', OroGen.rig.Tracker.front_pose_srv
      assert_equal({ %w[pose follow] => { %w[front pose] => {} } }, submodel.connections)
      assert_equal({ %w[pose follow] => { %w[pose pose] => {} } }, parent.connections)
    end

    # A model's connections are kept between generations: a connection or
    # an overload declared later, on it or on its parent, still shows.
    def test_connections_declared_after_they_were_read_show
      parent = new_cmp do
        add Rig::Services::Pose, as: 'pose'
        add OroGen.rig.Follower, as: 'follow'
      end
      submodel = parent.new_submodel
      assert_empty submodel.port_connections
      parent.pose_child.pose_port.connect_to parent.follow_child.pose_port
      assert_equal [%w[pose pose]], port_names(submodel)
      submodel.overload 'pose', OroGen.rig.Tracker.front_pose_srv
      assert_equal [%w[front pose]], port_names(submodel)
    end

    def port_names(model)
      model.port_connections.map { |c| [c.from.key.last, c.to.key.last] }
    end

    def test_connect_ports_connects_by_name_within_one_composition
      model = new_cmp do
        add OroGen.rig.Follower, as: 'follow'
        add OroGen.rig.Splitter, as: 'split'
      end
      model.follow_child.connect_ports(model.split_child, %w[command in] => { type: :buffer, size: 4 })
      assert_equal({ %w[follow split] => { %w[command in] => { type: :buffer, size: 4 } } }, model.connections)
      other = new_cmp { add OroGen.rig.Splitter, as: 'split' }
      assert_raises(ArgumentError) { model.follow_child.connect_ports(other.split_child, %w[command in] => {}) }
      error = assert_raises(Models::InvalidCompositionChildPort) do
        model.follow_child.connect_ports(model.split_child, %w[nope in] => {})
      end
      assert_match(/follow_child has no port 'nope'/, error.message)
    end

    def test_an_exported_port_is_a_port_of_the_composition_keeping_the_child_port
      model = new_cmp { add Rig::Services::Pose, as: 'pose' }
      exported = model.export model.pose_child.pose_port, as: 'where'
      assert_kind_of Models::OutputPort, exported
      assert_same model, exported.component_model
      assert_equal 'where', exported.name
      assert_equal Models::OutputPort.new(model, model.pose_child.pose_port.orogen_model, 'where'), exported
      assert_equal exported, model.find_port('where')
    end
  end
end
