# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Dynamic services of composition models, as in Syskit: each instance's
  # block changes the composition model itself (children, exports) and
  # provides the service on what it exports.
  class TestCompositionDynamicServices < Minitest::Test
    include CompositionTestHelper

    def setup
      super
      load_rig
      @model = Composition.new_submodel(name: 'Rig') { add OroGen.rig.Follower, as: 'follow' }
    end

    def test_an_instance_exports_and_provides_on_the_composition
      @model.dynamic_service Rig::Services::SpeedSource, as: 'speed' do
        add OroGen.rig.WheelDriver, as: 'wheel'
        export wheel_child.speed_port, as: "#{name}_out"
        provides Rig::Services::SpeedSource, as: name
      end
      service = @model.require_dynamic_service 'speed', as: 'left'
      assert_same service, @model.find_service('left')
      assert_equal ['left'], @model.each_required_dynamic_service.map(&:name)
      assert_equal @model.wheel_child.speed_port, @model.exported_outputs['left_out']
      assert_same service, @model.require_dynamic_service('speed', as: 'left')
    end

    def test_an_instance_must_provide_the_service
      @model.dynamic_service Rig::Services::SpeedSource, as: 'speed' do
        export follow_child.command_port
      end
      error = assert_raises(DeclarationError) { @model.require_dynamic_service 'speed', as: 'left' }
      assert_match(/provides no Rig::Services::SpeedSource as 'left'/, error.message)
    end

    def test_a_child_requires_the_dynamic_service_of_its_task_model
      task = TaskContext.new_submodel(name: 'Mux') { output_port 'out', '/double' }
      task.dynamic_service Rig::Services::SpeedSource, as: 'channel' do
        provides Rig::Services::SpeedSource, as: name
      end
      @model.add task, as: 'mux'
      service = @model.mux_child.require_dynamic_service 'channel', as: 'ch0'
      assert_equal 'ch0', service.name
      assert @model.mux_child.model.find_service('ch0')
      refute task.find_service('ch0')
      assert_equal @model.mux_child.out_port, @model.mux_child.ch0_srv.speed_out_port.to_component_port
    end
  end
end
