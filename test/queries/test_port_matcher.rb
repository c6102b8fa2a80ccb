# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'syskit/test/plan'

module Syskit
  module Queries
    # PortMatcher: the ports of matched tasks, by name or pattern and
    # type, and what is known of them without a plan.
    class TestPortMatcher < Minitest::Test
      include CompositionTestHelper

      def setup
        super
        load_rig
        @plan = Test::Plan.new
        @splitter = @plan.add(OroGen.rig.Splitter.new)
        @plan.add(OroGen.rig.Tracker.new)
      end

      def test_all_ports_of_the_tasks_by_default
        assert_equal [@splitter.in_port, @splitter.left_port, @splitter.right_port, @splitter.state_port].to_set,
                     PortMatcher.new(OroGen.rig.Splitter).to_set(@plan)
      end

      def test_name_and_pattern_filters
        assert_equal [@splitter.left_port], PortMatcher.new(OroGen.rig.Splitter).with_name('left').to_a(@plan)
        assert_equal [@splitter.left_port, @splitter.right_port].to_set,
                     PortMatcher.new(OroGen.rig.Splitter).with_name(/t$/).to_set(@plan)
      end

      def test_type_filter
        type = OroGen.rig.Tracker.front_port.type
        assert_empty PortMatcher.new(OroGen.rig.Splitter).with_type(type).to_a(@plan)
        assert_equal 2, PortMatcher.new(OroGen.rig.Tracker).with_type(type).to_a(@plan).size
      end

      def test_type_and_direction_are_resolved_from_an_exact_name
        matcher = PortMatcher.new(OroGen.rig.Splitter.match).with_name('in')
        assert_equal '/double', matcher.try_resolve_type.name
        assert_equal :input, matcher.try_resolve_direction
        assert_equal :output, PortMatcher.new(OroGen.rig.Splitter).with_name('left').try_resolve_direction
      end

      def test_nothing_is_resolved_from_a_pattern_or_an_unknown_name
        assert_nil PortMatcher.new(OroGen.rig.Splitter).with_name(/in/).try_resolve_type
        assert_nil PortMatcher.new(OroGen.rig.Splitter).with_name(/in/).try_resolve_direction
        assert_nil PortMatcher.new(OroGen.rig.Splitter).with_name('nothing').try_resolve_direction
      end

      def test_an_ambiguous_name_resolves_nothing
        component = ComponentMatcher.new.with_model([OroGen.rig.Follower, Rig::Services::Pose])
        assert_nil PortMatcher.new(component).with_name('pose').try_resolve_type
        assert_nil PortMatcher.new(component).with_name('pose').try_resolve_direction
      end
    end
  end
end

module Syskit
  # Syskit's errors raised without a message (+raise Ambiguous+, as a
  # mock does) say their class, as Ruby's own exceptions do.
  class TestErrorWithoutMessage < Minitest::Test
    def test_the_message_is_the_class_name
      assert_equal 'Syskit::Ambiguous', Ambiguous.new.message
      assert_equal 'Syskit::Ambiguous', assert_raises(Ambiguous) { raise Ambiguous }.message
    end
  end
end
