# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # What Rock's model code and tests call on service models and ports, and
  # Rock's base/float, as the gem provides them.
  class TestRockRubyHelpers < Minitest::Test
    include CompositionTestHelper

    def test_service_models_answer_syskit_s_questions
      load_rig
      odometry = Rig::Services::Odometry
      assert odometry.provides?(Rig::Services::Pose)
      refute Rig::Services::Pose.provides?(odometry)
      assert odometry.has_port?(:odometry)
      refute odometry.has_port?('pose')
      assert_equal odometry.odometry_port, odometry.find_output_port('odometry')
      assert_same odometry, odometry.odometry_port.component_model
      assert_equal RBS, Rig::Services::Pose.pose_port.orocos_type_name
      assert_equal RBS, Rig::Services::Pose.pose_port.type_name
    end

    # Syskit's service models include what they provide: Ruby's module
    # comparisons answer whether one provides another.
    def test_service_models_compare_as_modules
      load_rig
      odometry = Rig::Services::Odometry
      pose = Rig::Services::Pose
      assert_operator odometry, :<=, pose
      assert_operator odometry, :<, pose
      assert_operator pose, :<=, pose
      refute_operator pose, :<, pose
      refute_operator pose, :<=, odometry
      assert_operator pose, :>, odometry
      assert_operator pose, :>=, odometry
      assert_nil pose <= Comparable, 'unrelated modules: as Ruby answers'
    end

    def test_ports_say_whether_they_can_connect
      load_rig
      out = Rig::Services::Pose.pose_port
      assert out.can_connect_to?(OroGen.rig.Follower.find_port('pose'))
      refute out.can_connect_to?(OroGen.rig.Splitter.find_port('in'))
      refute OroGen.rig.Follower.find_port('pose').can_connect_to?(out)
    end

    def test_base_float_is_provided
      values = "require 'base/float'\nmodule Rig\n  VALUES = [Base.unset, Base.unknown].freeze\nend\n"
      app = load_app(rig_app({ 'models/values.rb' => values }))
      assert(Rig::VALUES.all?(&:nan?))
      assert Base.unset?(Float::NAN)
      refute Base.unknown?(1.0)
      assert Base.infinity?(Base.infinity)
      assert_empty app.problems.grep(NotModelled)
      app.unload
      refute Object.const_defined?(:Base, false), 'Base goes with the app'
    end

    def test_base_float_reopens_a_base_module_the_app_defines
      files = { 'models/a_base.rb' => "module Base\n  OLD = 1\nend\n",
                'models/values.rb' => "require 'base/float'\nmodule Rig\n  VALUES = [Base.unset].freeze\nend\n" }
      load_app(rig_app(files))
      assert Rig::VALUES.first.nan?
      assert_equal 1, Base::OLD
    end

    # Base comes with the base typekit, as Rock's Ruby plugin of it loads
    # base/float: it is the app's, which its files may reopen, and goes
    # with it.
    def test_base_is_the_app_s_own
      app = load_app(rig_app({ 'models/a_base.rb' => "module Base\n  OLD = 1\nend\n" }))
      assert Base.unknown.nan?
      assert_equal 1, Base::OLD
      app.unload
      load_app(rig_app({}))
      assert Base.unset.nan?
      refute Base.const_defined?(:OLD, false), 'the first app reopened its own Base'
    end
  end
end
