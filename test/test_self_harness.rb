# frozen_string_literal: true

require 'helper'
require 'json'

module Syskit
  # require 'syskit/test/self', the harness of Syskit's own test files
  # (rake conformance, which runs them, is test_conformance_task.rb): in
  # processes of their own, from a directory that is no app, as a Syskit
  # developer runs them.
  class TestSelfHarness < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

    # A test file of the shape of Syskit's: specs and a Minitest::Test
    # class, model definitions, plan-as-data, flexmock, runtime calls.
    SELF_TEST = <<~RUBY
      require 'syskit/test/self'

      describe Syskit::Models::Composition do
        let(:task) { Syskit::TaskContext.new_submodel(name: 'Probe').new }

        it 'defines models without an app' do
          srv = data_service_type 'Ranging'
          cmp = Syskit::Composition.new_submodel { add srv, as: 'ranger' }
          assert_same srv.placeholder_model, cmp.ranger_child.model
        end

        it 'gives each test a robot of its own' do
          assert_empty robot.devices
          sonar = Syskit::Device.new_submodel(name: 'Sonar')
          robot.device(sonar, as: 'sonar', using: Syskit::TaskContext.new_submodel { driver_for sonar, as: 'drv' })
          assert_equal ['sonar'], robot.each_master_device.map(&:name)
        end

        it 'holds tasks in the plan as data' do
          plan.add_mission_task(task)
          assert_equal [task], plan.find_tasks(task.model).to_a
          assert plan.mission_task?(task)
        end

        it 'mocks with flexmock' do
          double = flexmock(range: 3)
          assert_equal 3, double.range
        end

        it 'fails as asked' do
          assert_equal 1, 2
        end

        it 'skips what needs the runtime' do
          expect_execution { task.start! }
        end

        it 'skips the inside of Syskit' do
          Syskit::NetworkGeneration::MergeSolver.new(plan)
        end
      end

      class TC_Plain < Minitest::Test
        def test_a_test_class_has_the_harness_too
          assert_kind_of Syskit::Robot::RobotDefinition, robot
        end
      end
    RUBY

    def test_syskit_test_files_run_outside_an_app
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_shape.rb', SELF_TEST)
        report = File.join(dir, 'report.jsonl')
        out, err, = ruby_process('test/test_shape.rb', chdir: dir, env: { 'SYSKIT_CONFORMANCE_REPORT' => report })
        assert_match(/8 runs, \d+ assertions, 1 failures, 0 errors, 2 skips/, out, err)
        outcomes = File.readlines(report).map { |l| JSON.parse(l) }.to_h { |r| [r['name'], r] }
        assert_equal 'fail', outcomes.fetch('test_0005_fails as asked')['result']
        skip = outcomes.fetch('test_0006_skips what needs the runtime')
        assert_equal 'skip', skip['result']
        assert_match(/expect_execution .*runtime/, skip['message'])
        assert_equal 'pass', outcomes.fetch('test_a_test_class_has_the_harness_too')['result']
        internal = outcomes.fetch('test_0007_skips the inside of Syskit')
        assert_equal 'skip', internal['result']
        assert_match(/MergeSolver is the inside of Syskit's implementation/, internal['message'])
      end
    end

    def test_syskit_classes_the_gem_does_not_model_exist_only_under_the_harness
      out, err, status = ruby_process('-rsyskit', '-e', 'p defined?(Syskit::NetworkGeneration::MergeSolver)',
                                      chdir: GEM_ROOT)
      assert status.success?, err
      assert_equal "nil\n", out
    end

    def test_runtime_classes_and_helpers_outside_syskit_skip_too
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_runtime.rb', <<~RUBY)
          require 'syskit/test/self'

          describe 'runtime' do
            it('waits on threads') { Concurrent::CyclicBarrier.new(2) }
            it('makes a Roby app configuration') { Syskit::RobyApp::Configuration.new(Roby::Application.new) }
            it('logs while the engine runs') { capture_log(Syskit, :warn) { execution_engine } }
            it('makes the state of a running robot') { Roby::StateSpace.new }
          end
        RUBY
        report = File.join(dir, 'report.jsonl')
        out, err, = ruby_process('test/test_runtime.rb', chdir: dir, env: { 'SYSKIT_CONFORMANCE_REPORT' => report })
        assert_match(/4 runs, 0 assertions, 0 failures, 0 errors, 4 skips/, out, err)
        skipped = File.readlines(report).map { |l| JSON.parse(l)['message'].sub(/ needs Syskit's runtime .*/, '') }
        assert_equal %w[Concurrent::CyclicBarrier Syskit::Compat::Roby::StateSpace Syskit::RobyApp::Configuration
                        execution_engine], skipped.sort
      end
    end

    # Runtime entry points of Syskit's tests, after model-level calls.
    ENTRY_POINTS_TEST = <<~RUBY
      require 'syskit/test/self'

      describe 'entry points' do
        let(:task_m) { Syskit::TaskContext.new_submodel { output_port 'out', '/double' } }

        it('resolves types, then runs the plan') do
          assert_equal '/double', app.default_loader.resolve_type('/double').name
          plan.execution_engine
        end
        it('opens a transaction on the plan') { plan.in_transaction { flunk } }
        it('configures a stub deployment') { syskit_stub_deploy_and_configure(task_m, remote_task: false) }
        it('configures stubbed requirements') { syskit_stub_requirements_and_configure(task_m) }
        it('binds ports dynamically') { Syskit::Models::DynamicPortBinding.create(task_m.out_port) }
        it('reads a port') { flexmock(Syskit::DynamicPortBinding::OutputReader).new }
        it('deploys with a remote task') { syskit_stub_and_deploy(task_m, remote_task: false).out_port }
        it('marks an object as not marshallable') { Object.new.extend(Roby::DRoby::Unmarshallable) }
        it('binds ports of a matcher') { Syskit::Models::DynamicPortBinding.create_from_matcher(task_m.out_port) }
        it('stubs a remote deployment') { syskit_stub_configured_deployment(task_m, 'remote', remote_task: true) }
        it('sets up a plain component') { syskit_stub_and_deploy(Syskit::Component.new_submodel).setup }
        it('asks whether a task may be set up') { Syskit::Component.new.ready_for_setup? }
      end
    RUBY

    def test_runtime_calls_of_syskit_tests_skip_where_they_are_made
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_entry_points.rb', ENTRY_POINTS_TEST)
        report = File.join(dir, 'report.jsonl')
        out, err, = ruby_process('test/test_entry_points.rb', chdir: dir,
                                                              env: { 'SYSKIT_CONFORMANCE_REPORT' => report })
        assert_match(/12 runs, \d+ assertions, 0 failures, 0 errors, 10 skips/, out, err)
        messages = File.readlines(report).map { |l| JSON.parse(l)['message'] }.reject(&:empty?).sort
        called = messages.map { |m| m.delete_suffix(" needs Syskit's runtime (Roby and Orocos)") }
        assert_equal ['Syskit::Compat::Roby::DRoby::Unmarshallable', 'Syskit::DynamicPortBinding::OutputReader',
                      'Syskit::Models::DynamicPortBinding.create', 'Syskit::Models::DynamicPortBinding.create_from_matcher',
                      'plan.execution_engine', 'plan.in_transaction', 'syskit_stub_deploy_and_configure',
                      'syskit_stub_requirements_and_configure', 'task.ready_for_setup?', 'task.setup'], called
      end
    end

    def test_syskit_test_can_be_required_after_the_harness
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_both.rb', <<~RUBY)
          require 'syskit/test/self'
          require 'syskit/test'

          describe 'both' do
            it('runs') { assert_kind_of Syskit::Test::Plan, plan }
          end
        RUBY
        out, err, status = ruby_process('test/test_both.rb', chdir: dir)
        assert status.success?, "#{out}\n#{err}"
        assert_match(/1 runs, 1 assertions, 0 failures, 0 errors, 0 skips/, out)
      end
    end

    def test_models_a_test_defines_are_removed_after_it
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_cleanup.rb', <<~RUBY)
          require 'syskit/test/self'

          module Made; end

          describe 'model constants' do
            2.times do |i|
              it("defines Made::Srv (\#{i})") do
                refute Made.const_defined?(:Srv, false)
                Made.const_set(:Srv, data_service_type('Made::Srv'))
              end
            end
          end
        RUBY
        out, err, = ruby_process('test/test_cleanup.rb', chdir: dir)
        assert_match(/2 runs, \d+ assertions, 0 failures, 0 errors/, out, err)
      end
    end

    # Profile assertions on profiles made in Ruby and plain requirements.
    PROFILE_TEST = <<~RUBY
      require 'syskit/test/self'

      describe 'profile assertions' do
        before do
          @srv_m = Syskit::DataService.new_submodel(name: 'Ranging')
          @task_m = Syskit::TaskContext.new_submodel(name: 'Sonar')
          @task_m.provides @srv_m, as: 'ranging'
          @cmp_m = Syskit::Composition.new_submodel(name: 'Avoid')
          @cmp_m.add @srv_m, as: 'ranger'
          @profile = Syskit::Actions::Profile.new('Nav')
        end

        attr_reader :subject_syskit_model

        it('checks the profile the test is about') do
          @subject_syskit_model = @profile
          @profile.tag 'range', @srv_m
          @profile.define 'avoid', @cmp_m.use(@srv_m => @profile.range_tag)
          assert_is_self_contained
          e = assert_raises(Syskit::Test::ProfileAssertions::ProfileAssertionFailed) { assert_can_instanciate }
          assert_match(/Nav.avoid_def: cannot find a concrete implementation for profile:Nav.range_tag/, e.message)
        end

        it('names abstract services and tags of other profiles') do
          other = Syskit::Actions::Profile.new('Other')
          other.tag 'range', @srv_m
          @profile.define 'avoid', @cmp_m.use(@srv_m => other.range_tag)
          @profile.define 'open', @cmp_m
          e = assert_raises(Syskit::Test::ProfileAssertions::ProfileAssertionFailed) do
            assert_is_self_contained(@profile.avoid_def)
          end
          assert_match(/Nav.avoid_def contains tags from another profile: profile:Other.range_tag/, e.message)
          e = assert_raises(Syskit::Test::ProfileAssertions::ProfileAssertionFailed) do
            assert_can_instanciate(@profile.open_def)
          end
          assert_match(/cannot find a concrete implementation for Syskit::Models::Placeholder<Ranging>/, e.message)
        end

        it('resolves actions as Actions does in Syskit') do
          @profile.define 'avoid', @cmp_m.use(@srv_m => @task_m)
          @profile.define 'other', @cmp_m.use(@srv_m => @task_m)
          assert_equal %w[Nav.avoid_def], Actions(@profile, exclude: @profile.other_def).map(&:to_s)
        end

        it('skips the actions of Roby interfaces') do
          Actions(Roby::Actions::Interface.new_submodel.act)
        end

        it('checks plain requirements without a profile') do
          assert_can_instanciate(@cmp_m.use(@srv_m => @task_m))
        end

        it('fails as a test fails') do
          assert_is_self_contained(@cmp_m)
        end
      end
    RUBY

    # Network generation with the deployments a test declares.
    DEPLOY_TEST = <<~RUBY
      require 'syskit/test/self'

      describe 'deployments of a test' do
        before { @task_m = Syskit::TaskContext.new_submodel(name: 'Probe') }

        it('deploys with use_deployment') do
          use_deployment @task_m => 'probe_task'
          assert_equal 'probe_task', syskit_deploy(@task_m).orocos_name
        end

        it('prefers the deployment of the requirement') do
          use_deployment @task_m => 'test_level'
          assert_equal 'own', syskit_deploy(@task_m.deployed_as('own')).orocos_name
        end

        it('deploys with a stub deployment model') do
          use_deployment syskit_stub_deployment_model(@task_m, 'stubbed')
          assert_equal 'stubbed', syskit_deploy(@task_m).orocos_name
        end

        it('deploys with a stub configured deployment') do
          configured = syskit_stub_configured_deployment(@task_m, 'configured')
          assert_equal 'stubs', configured.process_server_name
          assert_equal 'configured', syskit_deploy(@task_m).orocos_name
        end

        it('takes what answers to_action') do
          use_deployment @task_m => 'probe_task'
          assert_kind_of @task_m, syskit_deploy(flexmock(to_action: @task_m))
        end

        it('fails without a deployment') do
          assert_raises(Syskit::DeploymentError) { syskit_deploy(@task_m) }
        end

        it('generates without deploying') do
          task = syskit_generate_network(@task_m)
          assert_kind_of @task_m, task
          assert_nil task.orocos_name
        end

        it('stubs a task model named in the call') do
          task = syskit_stub_and_deploy('Probe') { output_port 'out', '/double' }
          assert_equal 'Probe', task.model.name
          assert_equal 'out', task.model.out_port.name
        end

        it('skips the actions of Roby planners') do
          syskit_deploy(Roby::Actions::Interface.new_submodel.some_action)
        end
      end
    RUBY

    def test_networks_are_generated_and_deployed_with_the_deployments_the_test_declares
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_deploy.rb', DEPLOY_TEST)
        out, err, = ruby_process('test/test_deploy.rb', '-v', chdir: dir)
        assert_match(/9 runs, \d+ assertions, 0 failures, 0 errors, 1 skips/, out, err)
        assert_match(/a Roby planner's result\) needs Syskit's runtime/, out)
      end
    end

    def test_profile_assertions_raise_syskit_s_failure_with_its_words
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_profiles.rb', PROFILE_TEST)
        out, err, = ruby_process('test/test_profiles.rb', chdir: dir)
        assert_match(/6 runs, \d+ assertions, 1 failures, 0 errors, 1 skips/, out, err)
        assert_match(/Avoid is not self contained/, out)
      end
    end
  end
end
