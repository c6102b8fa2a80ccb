# frozen_string_literal: true

require 'helper'

module Syskit
  # A deployment model as a robot configuration uses it
  # (Models::ConfiguredDeployment): renamed tasks, read-only tasks.
  class TestConfiguredDeploymentModel < Minitest::Test
    def setup
      super
      @task_m = TaskContext.new_submodel(name: 'Camera')
      task_m = @task_m
      @model = Syskit::Deployment.new_submodel(name: 'cameras') do
        task 'left', task_m
        task 'right', task_m
      end
    end

    def teardown
      Syskit::Deployment.clear_submodels
      super
    end

    def test_its_spec_renames_tasks_and_leaves_the_model_s_alone
      configured = Models::ConfiguredDeployment.new('stubs', @model, { 'left' => 'front_left' })
      assert_equal %w[front_left right], configured.orogen_model.task_activities.map(&:name)
      assert_equal %w[left right], @model.orogen_model.task_activities.map(&:name)
      assert_equal @task_m.orogen_model, configured.orogen_model.task_activities.first.context
    end

    def test_mappings_may_be_written_without_braces
      configured = Models::ConfiguredDeployment.new('stubs', @model, 'right' => 'back')
      assert_equal({ 'left' => 'left', 'right' => 'back' }, configured.name_mappings)
    end

    def test_a_deployment_made_from_it_has_its_server_and_read_only_tasks
      configured = Models::ConfiguredDeployment.new('stubs', @model, { 'left' => 'a_left' }, read_only: /^a_/)
      deployment = configured.new
      assert_equal 'stubs', deployment.arguments[:on]
      assert_equal %w[a_left], deployment.arguments[:read_only]
      all = Models::ConfiguredDeployment.new('stubs', @model, read_only: true)
      assert_equal %w[left right], all.new.arguments[:read_only]
    end

    def test_read_only_names_a_renamed_task
      error = assert_raises(ArgumentError) do
        Models::ConfiguredDeployment.new('stubs', @model, { 'left' => 'a_left' }, read_only: 'left')
      end
      assert_match(/valid deployed task names are \["a_left", "right"\]/, error.message)
    end
  end
end
