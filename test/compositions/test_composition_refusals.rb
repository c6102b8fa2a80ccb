# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # The composition statements Syskit refuses with an ArgumentError.
  class TestCompositionRefusals < Minitest::Test
    include CompositionTestHelper::OnRig

    def setup
      super
      @model = new_cmp do
        add OroGen.rig.Follower, as: 'follow'
        add OroGen.rig.Splitter, as: 'split'
        export follow_child.command_port, as: 'out'
      end
    end

    # Where Syskit raises ArgumentError on a composition model's
    # statements, the gem's located error is one, and the model is unchanged.
    def test_exporting_two_ports_under_one_name
      assert_refused(/already exports .*command_port as 'out'/) do
        @model.export @model.split_child.left_port, as: 'out'
      end
      assert_equal %w[out], @model.exports.keys
    end

    def test_exporting_a_port_that_is_not_a_childs
      assert_refused(/export expects a port of a child/) { @model.export OroGen.rig.Follower.command_port, as: 'cmd' }
    end

    def test_add_without_a_name
      assert_refused(/add needs a child name/) { @model.add OroGen.rig.Follower }
      assert_equal %w[follow split], @model.child_names.sort
    end

    def test_connecting_the_children_of_two_composition_models
      other = new_cmp { add OroGen.rig.Splitter, as: 'split' }
      assert_refused(/is not a port of a child of/) do
        @model.follow_child.command_port.connect_to other.split_child.in_port
      end
      assert_empty @model.connections
    end

    def assert_refused(message, &)
      error = assert_raises(ArgumentError, message.source, &)
      assert_match message, error.message
    end

    # Syskit's add_main counts the main child a submodel inherits: a
    # second one is an ArgumentError, not a silent replacement.
    def test_a_submodel_cannot_add_a_second_main_child
      parent = new_cmp { add_main OroGen.rig.Follower, as: 'follow' }
      child = parent.new_submodel
      error = assert_raises(ArgumentError) { child.add_main(OroGen.rig.Splitter, as: 'split') }
      assert_match(/already has a main child \(follow\) \(from #{Regexp.escape(parent.to_s)}\)/, error.message)
      assert_equal 'follow', child.main_task.child_name
      refute child.find_child('split'), 'the refused child stays out of the model'
    end
  end
end
