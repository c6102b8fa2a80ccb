# frozen_string_literal: true

require 'helper'
require 'pp'

module Syskit
  # Component models made in Ruby, as Syskit's own tests make them
  # (Syskit::Component.new_submodel), and what a model knows of its
  # submodels.
  class TestComponentModels < Minitest::Test
    def test_a_component_model_made_in_ruby_is_named_as_asked_and_is_a_model
      model = Component.new_submodel(name: 'Arm')
      assert_equal 'Arm', model.name
      assert_equal 'Arm', model.short_name
      assert Models.is_model?(model)
      assert Models.is_model?(Component)
      assert_kind_of model, model.new
    end

    def test_a_component_model_knows_its_submodels_until_it_clears_them
      root = Component.new_submodel
      child = root.new_submodel
      grandchild = child.new_submodel
      other = root.new_submodel
      assert root.has_submodel?(grandchild)
      assert Component.has_submodel?(grandchild)

      child.clear_submodels
      refute child.has_submodel?(grandchild)
      refute root.has_submodel?(grandchild)
      assert root.has_submodel?(other)

      root.clear_submodels
      refute root.has_submodel?(child)
    end

    module Named; end

    def test_clearing_submodels_removes_their_constants_but_keeps_the_gems_own_models
      root = TaskContext.new_submodel
      model = root.new_submodel
      Named.const_set(:Task, model)
      assert root.has_submodel?(model)
      root.clear_submodels
      refute root.has_submodel?(model)
      refute TaskContext.has_submodel?(model)
      refute Named.const_defined?(:Task, false)
      assert Models::ComponentSubmodels.permanent?(RubyTaskContext)
      refute Models::ComponentSubmodels.permanent?(root)
    end

    def test_a_service_bound_to_a_component_is_a_model
      srv = DataService.new_submodel
      task = Component.new_submodel { provides srv, as: 'srv' }
      assert Models.is_model?(task.srv_srv)
    end

    def test_an_invalid_auto_connection_lists_the_ports_it_looked_at
      double = Types::OpaqueType.new('/double')
      source = TaskContext.new_submodel(name: 'Source') { output_port 'out', double }
      sink = TaskContext.new_submodel(name: 'Sink') { input_port 'in', double }
      text = PP.pp(InvalidAutoConnection.new(source, sink), +'')
      assert_match(%r{the outputs of Source are\s+out\[/double\]}, text)
      assert_match(%r{the inputs of Sink are\s+in\[/double\]}, text)
    end

    def test_a_dynamic_service_block_is_evaluated_on_an_instantiation_context
      srv = DataService.new_submodel
      task = TaskContext.new_submodel
      dynamic = task.dynamic_service(srv, as: 'dyn') { provides srv }
      context = Models::DynamicDataService::InstantiationContext.new(task, 'one', dynamic, frame: 'body')
      assert_equal({ frame: 'body' }, context.options)
      bound = context.provides(srv)
      assert_equal 'one', bound.name
      assert_raises(ArgumentError) { context.provides(srv) }
    end

    def test_a_provides_whose_ports_do_not_fit_is_an_invalid_provides
      double = Types::OpaqueType.new('/double')
      srv = DataService.new_submodel { output_port 'out', double }
      task = TaskContext.new_submodel { input_port 'out', double }
      assert_raises(InvalidProvides) { task.provides(srv, as: 'srv') }
      assert_raises(InvalidProvides) { task.provides(srv, { 'nothing' => 'out' }, as: 'srv') }
      assert_raises(ArgumentError) { task.provides(srv, as: 'srv') }
    end

    def test_a_dynamic_service_records_what_syskit_does_with_running_components
      srv = DataService.new_submodel
      task = TaskContext.new_submodel
      plain = task.dynamic_service(srv, as: 'plain') { provides srv }
      assert_same task, plain.component_model
      assert_same srv, plain.service_model
      assert plain.addition_requires_reconfiguration?
      assert plain.remove_when_unused?
      refute task.dynamic_service(srv, as: 'live', dynamic: true) { provides srv }.addition_requires_reconfiguration?
    end

    def test_the_dynamic_option_of_a_dynamic_service_is_deprecated
      srv = DataService.new_submodel
      task = TaskContext.new_submodel
      level = ENV.fetch('SYSKIT_LOG', nil)
      ENV['SYSKIT_LOG'] = 'debug'
      _, err = capture_io { task.dynamic_service(srv, as: 'live', dynamic: true) { provides srv } }
      assert_match(/dynamic: of dynamic_service is deprecated, write addition_requires_reconfiguration: false/, err)
      assert_empty capture_io { task.dynamic_service(srv, as: 'plain') { provides srv } }[1]
    ensure
      ENV['SYSKIT_LOG'] = level
    end

    def test_a_ruby_task_model_declares_dynamic_ports_its_dynamic_services_create
      double = Types::OpaqueType.new('/double')
      srv = DataService.new_submodel { output_port 'out', double }
      task = TaskContext.new_submodel { dynamic_output_port(/\w+_out/, double) }
      task.dynamic_service(srv, as: 'dyn') { provides srv, 'out' => "#{name}_out" }
      made = task.specialize
      made.require_dynamic_service('dyn', as: 'left')
      port = made.left_srv.out_port
      assert_equal 'out', port.name
      assert_equal 'left_out', port.to_component_port.name
    end

    def test_a_proxy_task_is_an_abstract_task_of_the_model
      model = Component.new_submodel
      task = model.create_proxy_task
      assert_kind_of model, task
      assert task.abstract?
      refute model.new.abstract?
    end

    def test_any_component_model_may_drive_a_device_held_in_its_dev_argument
      device = Device.new_submodel(name: 'Imu')
      model = Component.new_submodel { driver_for device, as: 'imu' }
      assert_same model.imu_srv, model.find_data_service_from_type(device)
      assert model.has_argument?(:imu_dev)
      refute model.has_argument?(:other_dev)
      refute Component.new_submodel.has_argument?(:imu_dev)
    end

    def test_a_private_specialization_is_not_among_the_models_it_fullfills
      model = Component.new_submodel
      specialized = model.specialize
      assert_includes specialized.fullfilled_model, model
      refute_includes specialized.fullfilled_model, specialized
      assert_includes model.fullfilled_model, model
    end

    def test_a_component_model_may_provide_a_roby_task_service
      service = Compat::Roby::TaskService.new_submodel(name: 'Logger')
      model = Component.new_submodel { provides service }
      assert model.fullfills?(service)
      assert_includes model.fullfilled_model, service
      assert_kind_of service, model.new
      refute Component.new_submodel.fullfills?(service)
    end

    def dynamic_task_model
      srv = DataService.new_submodel
      TaskContext.new_submodel { dynamic_service(srv, as: 'dyn') { provides srv } }
    end

    def test_two_specializations_merge_into_a_new_one_with_the_services_of_both
      base = dynamic_task_model
      left = base.specialize
      left.require_dynamic_service('dyn', as: 'left')
      right = base.specialize
      right.require_dynamic_service('dyn', as: 'right')
      merged = left.merge(right)
      assert merged.private_specialization?
      assert_same base, merged.superclass
      assert merged.left_srv
      assert merged.right_srv
      assert_nil left.find_data_service('right')
      assert_nil right.find_data_service('left')
    end

    def test_a_specialization_merged_with_a_submodel_specializes_the_submodel
      base = dynamic_task_model
      left = base.specialize
      left.require_dynamic_service('dyn', as: 'left')
      sub = base.new_submodel
      merged = left.merge(sub.specialize)
      assert_same sub, merged.superclass
      assert merged.left_srv
      assert_raises(IncompatibleComponentModels) { left.merge(dynamic_task_model.specialize) }
    end

    def test_required_dynamic_services_are_a_list_for_any_component
      assert_empty Component.new_submodel.each_required_dynamic_service
      assert_empty Component.new_submodel.new.each_required_dynamic_service
      model = dynamic_task_model.new_submodel
      srv = model.require_dynamic_service('dyn', as: 'one')
      assert_equal [srv], model.each_required_dynamic_service
      task = model.new
      assert_equal [srv.bind(task)], task.each_required_dynamic_service
    end

    def test_a_model_as_plan_is_a_task_standing_for_its_requirements
      model = Component.new_submodel { argument :speed }
      task = model.as_plan(speed: 2)
      assert_kind_of model, task
      assert_equal 2, task.speed
      assert_equal model.to_instance_requirements.with_arguments(speed: 2), task.requirements
      assert task.planning_task
    end

    def test_a_dynamic_service_block_that_provides_nothing_is_an_invalid_block
      srv = DataService.new_submodel
      task = TaskContext.new_submodel
      dynamic = task.dynamic_service(srv, as: 'dyn') { nil }
      error = assert_raises(InvalidDynamicServiceBlock) { dynamic.instanciate('one') }
      assert_match(/the block of dynamic service 'dyn' of .* provides nothing for 'one'/, error.message)
      assert_equal [File.expand_path(__FILE__), __LINE__ - 3], [error.location.path, error.location.lineno]
      assert_match(/call provides/, error.hint)
    end

    def test_compute_port_mappings_binds_a_service_as_provides_would
      double = Types::OpaqueType.new('/double')
      srv = DataService.new_submodel { output_port 'pose', double }
      task = TaskContext.new_submodel do
        output_port 'a', double
        output_port 'b', double
      end
      assert_equal({ 'pose' => 'b' }, task.compute_port_mappings(srv, 'pose' => 'b'))
      error = assert_raises(InvalidPortMapping) { task.compute_port_mappings(srv) }
      assert_equal File.expand_path(__FILE__), error.location.path
      assert_nil task.find_data_service('pose'), 'nothing declared'
    end
  end
end
