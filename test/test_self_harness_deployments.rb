# frozen_string_literal: true

require 'helper'

module Syskit
  # Deployments under Syskit's harness: the deployment groups of profiles
  # and requirements, tags stubbed, and what a profile assertion says when
  # tasks have no deployed task.
  class TestSelfHarnessDeployments < Minitest::Test
    parallelize_me!

    DEPLOY_TEST = <<~RUBY
      require 'syskit/test/self'

      describe 'deployments' do
        before do
          @task_m = Syskit::TaskContext.new_submodel(name: 'Probe')
          @cmp_m = Syskit::Composition.new_submodel(name: 'Survey')
          @cmp_m.add @task_m, as: 'probe'
          @profile = Syskit::Actions::Profile.new('Field')
        end

        it('lists each task without a deployed task and what needs it') do
          @profile.define 'survey', @cmp_m
          e = assert_raises(Syskit::Test::ProfileAssertions::ProfileAssertionFailed) { assert_can_deploy(@profile) }
          assert_match(/Field.survey_def: cannot deploy the following tasks: Probe \\(child probe of Survey\\)/,
                       e.message)
        end

        it('deploys the definitions of a profile with its deployments') do
          @profile.use_deployment syskit_stub_deployment_model(@task_m, 'field_probe')
          @profile.define 'survey', @cmp_m
          assert_can_deploy(@profile)
          assert_equal 'field_probe', syskit_deploy(@profile.survey_def).probe_child.deployed_task.name
        end

        it('deploys a network with the deployments of its requirements, which merged tasks keep') do
          group = Syskit::Models::DeploymentGroup.new
          group.use_deployment(@task_m => 'own_probe')
          @profile.define 'survey', @cmp_m
          assert_can_deploy(@cmp_m.to_instance_requirements.use_deployment_group(group))
          assert_can_deploy(@profile.survey_def, together_with: @task_m.to_instance_requirements.use_deployment_group(group))
          refute_same group, @task_m.to_instance_requirements.deployment_group
        end

        it('deploys from the nearest deployments up the network') do
          cmp = syskit_deploy(@cmp_m.use('probe' => @task_m.use_deployment(@task_m => 'inner'))
                                    .use_deployment(@task_m => 'outer'))
          assert_equal 'inner', cmp.probe_child.deployed_task.name
        end

        it('gives the deployments of the test as its default deployment group') do
          use_deployment @task_m => 'test_probe'
          assert_equal %w[test_probe], default_deployment_group.deployed_tasks.map(&:name)
        end

        it('has the stubs process server, as Syskit does') do
          use_deployment @task_m => 'stub_probe', on: 'stubs'
          assert_equal 'stubs', default_deployment_group.process_server_of('stub_probe')
        end

        it('skips deploying the plan of a running system') do
          assert_raises(Roby::Test::ExecutionExpectations::UnexpectedErrors) { deploy_current_plan }
        end

        it('skips running planners') { syskit_run_planner_with_full_deployment { flunk } }

        it('stubs tags') do
          srv_m = Syskit::DataService.new_submodel(name: 'Ranging')
          @profile.tag 'range', srv_m
          @cmp_m.add srv_m, as: 'ranger'
          cmp = syskit_stub_and_deploy(@cmp_m.use('ranger' => @profile.range_tag))
          assert cmp.ranger_child.fullfills?(srv_m)
        end
      end
    RUBY

    def test_deployments_of_profiles_and_requirements_under_the_harness
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_deploy.rb', DEPLOY_TEST)
        out, err, = ruby_process('test/test_deploy.rb', chdir: dir)
        assert_match(/9 runs, \d+ assertions, 0 failures, 0 errors, 2 skips/, out, err)
      end
    end
  end
end
