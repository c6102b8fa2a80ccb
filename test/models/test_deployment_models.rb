# frozen_string_literal: true

require 'helper'

module Syskit
  # Deployment models (Syskit::Deployment and Models::Deployment): each
  # stands for one deployment spec, made from the root or a submodel.
  class TestDeploymentModels < Minitest::Test
    def teardown
      Syskit::Deployment.clear_submodels
      ::Deployments.send(:remove_const, :CameraProcess) if defined?(::Deployments::CameraProcess)
      super
    end

    def test_a_submodel_stands_for_a_spec_whose_tasks_its_block_declares
      task_m = TaskContext.new_submodel(name: 'Camera')
      model = Syskit::Deployment.new_submodel(name: 'cameras') { task 'left', task_m }
      assert model < Syskit::Deployment
      assert_equal 'cameras', model.deployment_name
      assert_equal([['left', task_m]], model.orogen_model.task_activities.map { |t| [t.name, t.model] })
      assert_same model, Syskit::Deployment.model_for(model.orogen_model)
    end

    def test_submodels_are_enumerated_and_cleared_with_their_submodels
      parent = Syskit::Deployment.new_submodel(name: 'a')
      child = parent.new_submodel(name: 'b')
      assert Syskit::Deployment.has_submodel?(child)
      assert parent.has_submodel?(child)
      parent.clear_submodels
      refute Syskit::Deployment.has_submodel?(child)
      refute Syskit::Deployment.has_model_for?(child.orogen_model)
      assert Syskit::Deployment.has_submodel?(parent)
    end

    def test_the_namespace_of_registered_deployments_exists_before_any_is_registered
      out, err, status = Open3.capture3(SelfTest.child_env, RbConfig.ruby, '-I', File.join(GEM_ROOT, 'lib'), '-rsyskit',
                                        '-e', 'p Deployments.constants', unsetenv_others: true)
      assert status.success?, err
      assert_equal "[]\n", out
    end

    def test_a_named_spec_can_be_registered_as_a_constant
      spec = Models.create_orogen_deployment_model('camera_process')
      model = Syskit::Deployment.define_from_orogen(spec, register: true)
      assert_same model, ::Deployments::CameraProcess
      assert_same spec, model.orogen_model
      anonymous = Syskit::Deployment.define_from_orogen(Models.create_orogen_deployment_model, register: true)
      assert_nil anonymous.deployment_name
    end

    def test_a_deployment_instance_keeps_its_arguments
      model = Syskit::Deployment.new_submodel(name: 'a')
      assert_equal({ on: 'stubs' }, model.new(on: 'stubs').arguments)
    end
  end
end
