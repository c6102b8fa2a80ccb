# frozen_string_literal: true

require 'helper'

module Syskit
  # Deployment models by name (Syskit's OroGen.deployments).
  class TestDeploymentNamespace < Minitest::Test
    def setup
      @app = load_app(write_app({}))
      @namespace = OroGenNamespace::DeploymentNamespace.new
      @model = Syskit::Deployment.new_submodel(name: 'camera_process')
    end

    def teardown
      @namespace.clear
      ::OroGen.syskit_model_constant_registration = false
      super
    end

    def test_a_registered_deployment_is_a_reader_of_the_namespace
      @namespace.register_syskit_model(@model)
      assert_same @model, @namespace.camera_process
      assert_equal [@model], @namespace.each.to_a
      error = assert_raises(NoMethodError) { @namespace.lidar_process }
      assert_match(/#<deployments: camera_process>/, error.message)
    end

    def test_constants_are_registered_only_when_asked_and_removed_on_clear
      @namespace.register_syskit_model(@model)
      refute ::Deployments.const_defined?(:CameraProcess, false)
      @namespace.clear
      ::OroGen.syskit_model_constant_registration = true
      @namespace.register_syskit_model(@model)
      assert_same @model, ::Deployments::CameraProcess
      @namespace.clear
      refute ::Deployments.const_defined?(:CameraProcess, false)
      refute_respond_to @namespace, :camera_process
    end
  end
end
