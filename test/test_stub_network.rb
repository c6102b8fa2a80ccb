# frozen_string_literal: true

require 'compositions/composition_test_helper'
require 'syskit/test/plan'
require 'syskit/test/stub_network'

module Syskit
  # Test::StubNetwork: the abstract tasks of a network already in a plan
  # are replaced by stubs, and plan services follow the replacements.
  class TestStubNetwork < Minitest::Test
    include CompositionTestHelper

    attr_reader :plan

    def setup
      super
      load_rig
      @plan = Test::Plan.new
      @cmp_m = Composition.new_submodel do
        add Rig::Services::Pose, as: 'pose'
        add OroGen.rig.Follower, as: 'follower'
      end
    end

    def test_an_abstract_child_is_replaced_by_a_stub_providing_its_services
      cmp = @cmp_m.instanciate(plan)
      placeholder = cmp.pose_child
      follower = cmp.follower_child
      result = Test::StubNetwork.new(self).apply([cmp])
      assert_equal [cmp], result
      refute cmp.pose_child.abstract?
      assert cmp.pose_child.fullfills?(Rig::Services::Pose)
      assert_same follower, cmp.follower_child
      refute plan.include?(placeholder)
      assert plan.include?(cmp.pose_child)
    end

    def test_a_device_model_is_stubbed_by_the_driver_of_a_stub_device
      sonar = Device.new_submodel(name: 'Sonar')
      cmp_m = Composition.new_submodel { add sonar, as: 'sonar' }
      cmp = Test::StubNetwork.new(self).apply([cmp_m.instanciate(plan)]).first
      assert_kind_of sonar, cmp.sonar_child
      assert_equal sonar, cmp.sonar_child.dev0_dev.model
    end

    def test_a_driver_without_a_device_is_instanciated_and_stubbed_a_device
      lamp = Device.new_submodel(name: 'Lamp')
      driver = TaskContext.new_submodel(name: 'LampDriver') { driver_for lamp, as: 'lamp' }
      cmp_m = Composition.new_submodel { add driver, as: 'lamp' }
      cmp = cmp_m.instanciate(plan)
      refute cmp.lamp_child.arguments.set?(:lamp_dev)
      Test::StubNetwork.new(self).apply([cmp])
      assert_equal lamp, cmp.lamp_child.lamp_dev.model
    end

    def test_a_model_as_plan_is_a_task_to_be_planned_for_its_requirements
      task = @cmp_m.as_plan
      assert_kind_of @cmp_m, task
      assert_equal @cmp_m.to_instance_requirements, task.planning_task.requirements
    end

    def test_plan_services_follow_the_replaced_tasks
      cmp = @cmp_m.instanciate(plan)
      root = cmp.as_service
      child = cmp.pose_child.as_service
      final = Test::StubNetwork.new(self).apply([cmp]).first
      assert_same final, root.to_task
      assert_same final.pose_child, child.to_task
      refute child.to_task.abstract?
    end

    def test_an_abstract_root_is_replaced
      task = plan.add(Rig::Services::Pose.placeholder_model.new)
      plan.add_mission_task(task)
      final = Test::StubNetwork.new(self).apply([task]).first
      refute_same task, final
      refute final.abstract?
      assert plan.mission_task?(final)
      refute plan.include?(task)
    end

    def test_a_task_marked_abstract_is_not_abstract_once_marked_otherwise
      task = OroGen.rig.Follower.new
      task.abstract = true
      assert task.abstract?
      task.abstract = false
      refute task.abstract?
    end
  end
end
