# frozen_string_literal: true

require 'helper'

module Syskit
  # Syskit's specialize, require_dynamic_service and with_dynamic_service
  # on task models, as common_models' tests and helpers write them: an
  # instance of a dynamic service becomes a service of a specialization of
  # the task model, with the ports it creates; the specialization drives
  # devices, runs on the task model's deployments, and its configure method
  # sees the instance among its required dynamic services.
  class TestRequiredDynamicServices < Minitest::Test
    FILES = {
      'models/devices/camera.rb' => <<~RUBY,
        module MyApp
          module Devices
            device_type 'Camera' do
              output_port 'frame', '/double'
            end
            data_service_type 'Light' do
              output_port 'level', '/double'
            end
          end
        end
      RUBY
      'models/orogen/rig.orogen' => <<~RUBY,
        name 'rig'
        task_context 'Task' do
          property 'exports', 'int', 0
          property 'summary', '/std/string', ''
          output_port 'main_frame', '/double'
          dynamic_output_port(/^\\w+_frame$/, '/double')
          dynamic_output_port(/^\\w+_level$/, '/double')
        end
      RUBY
      'models/orogen/rig.rb' => <<~RUBY,
        require 'models/devices/camera'
        Syskit.extend_model OroGen.rig.Task do
          provides MyApp::Devices::Light, as: 'lamp', 'level' => 'main_frame'
          dynamic_service MyApp::Devices::Camera, as: 'export' do
            driver_for MyApp::Devices::Camera, 'frame' => "\#{options.fetch(:prefix, name)}_frame"
          end
          dynamic_service MyApp::Devices::Light, as: 'dimmer' do
            provides MyApp::Devices::Light, 'level' => "\#{name}_level"
          end

          def configure
            super
            properties.exports = each_required_dynamic_service.count
            properties.summary = each_required_dynamic_service.map { |srv| describe_export(srv) }.join(' ')
          end

          # What a configure method reads of an instance: its name and
          # options, the task port behind a service port, the device.
          def describe_export(srv)
            parts = [srv.name, srv.model.dynamic_service_options.fetch(:prefix, '-')]
            if srv.fullfills?(MyApp::Devices::Camera)
              parts << srv.as(MyApp::Devices::Camera).frame_port.to_component_port.name
              parts << find_device_attached_to(srv).name
            end
            parts.join(':')
          end
        end
      RUBY
      'config/robots/default.rb' => "using_task_library 'rig'\nSyskit.conf.use_deployment OroGen.rig.Task => 'rig'\n"
    }.freeze

    def load_robot(robot, files = {})
      @root = my_app(robot, FILES.merge(files), libraries: %w[rig])
      @app = load_app(@root, problems: true)
      @app.problems.first
    end

    def plan
      Network::Generator.plan_profile(@app, MyApp::Profiles::Base.syskit_profile).plan
    end

    def test_a_specialization_requires_an_instance_of_a_dynamic_service
      assert_nil load_robot(nil)
      task_model = OroGen.rig.Task
      model = task_model.specialize
      rear = model.require_dynamic_service('export', as: 'rear', prefix: 'back')
      assert_equal 'rig::Task{1}', model.name
      assert model.specialization?
      assert_same task_model, model.concrete_model
      assert_equal [MyApp::Devices::Camera, 'rear', { 'frame' => 'back_frame' }],
                   [rear.model, rear.full_name, rear.port_mappings]
      assert_same rear, model.find_data_service('rear')
      assert model.find_port('back_frame').dynamic?
      assert_same rear, model.require_dynamic_service('export', as: 'rear'), 'asked again: the same service'
      assert_equal [rear], model.required_dynamic_services
      assert_task_model_unchanged
    end

    def test_the_options_of_an_instance
      assert_nil load_robot(nil)
      model = OroGen.rig.Task.specialize
      model.require_dynamic_service('export', as: 'rear', prefix: 'back')
      assert_equal [{ prefix: 'back' }], model.each_required_dynamic_service.map(&:dynamic_service_options)
      assert_same model, model.ensure_model_is_specialized
    end

    # Helpers of real bundles specialize the model they are given when it
    # is not one already.
    def test_ensure_model_is_specialized
      assert_nil load_robot(nil)
      made = OroGen.rig.Task.ensure_model_is_specialized
      assert_equal ['rig::Task{1}', OroGen.rig.Task], [made.name, made.concrete_model]
      assert_empty OroGen.rig.Task.each_required_dynamic_service.to_a
    end

    def assert_task_model_unchanged
      assert_nil OroGen.rig.Task.find_data_service('rear')
      assert_nil OroGen.rig.Task.find_port('back_frame')
      assert_equal 'rig::Task{2}', OroGen.rig.Task.specialize.name
    end

    def test_a_device_driven_by_a_specialization_runs_on_a_deployment_of_the_task_model
      assert_nil load_robot(<<~RUBY)
        rear = OroGen.rig.Task.specialize
        rear.require_dynamic_service('export', as: 'rear')
        device(Devices::Camera, as: 'rear_cam', using: rear)
      RUBY
      task = plan.find_task('rig')
      assert_equal 'rig::Task{1}', task.model
      assert_includes task.ports.map(&:name), 'rear_frame'
      assert_equal 1, task.properties['exports']
      assert_equal 'rear:-:rear_frame:rear_cam', task.properties['summary']
      assert_equal ['rear_cam'], task.devices
    end

    # using: takes requirements of the driver, as Syskit does: the device
    # takes over their sections, deployment hints and deployment.
    def test_a_device_driven_by_requirements
      assert_nil load_robot(<<~RUBY, 'config/robots/default.rb' => "using_task_library 'rig'\n")
        rear = OroGen.rig.Task.with_dynamic_service('export', as: 'rear', prefix: 'back')
        device(Devices::Camera, as: 'rear_cam', using: rear.deployed_as('rear_rig'))
      RUBY
      device = MyApp::Profiles::Base.rear_cam_dev.device
      assert_equal ['rig::Task{1}', 'rear_rig'], [device.using.name, device.declared_deployment.name]
      task = plan.find_task('rear_rig')
      assert_equal 'rear:back:back_frame:rear_cam', task.properties['summary']
    end

    def test_a_device_driven_by_requirements_with_arguments
      error = load_robot(<<~RUBY)
        device(Devices::Camera, as: 'rear_cam', using: OroGen.rig.Task.with_arguments(speed: 2))
      RUBY
      assert_reported error, /using: takes a driver task model, or its with_conf, prefer_deployed_tasks and deploy/,
                      at: 'models/profiles/base.rb:7', hint: /chained calls/, root: @root
    end

    # The transformer is not modelled: use_frames warns, once, where it is
    # written, and the definition plans as if it were not there.
    def test_use_frames_is_not_modelled
      load_robot(nil, 'models/profiles/base.rb' => <<~RUBY)
        using_task_library 'rig'
        module MyApp
          module Profiles
            profile 'Base' do
              define 'side', OroGen.rig.Task.with_dynamic_service('dimmer', as: 'side').use_frames('world' => 'map')
            end
          end
        end
      RUBY
      warnings = @app.problems.grep(NotModelled)
      assert_equal 1, warnings.size
      assert_reported warnings.first, /use_frames on rig::Task\{1\} \(the transformer\)/,
                      at: 'models/profiles/base.rb:5', root: @root
      assert_equal 'side:-', plan.find_task('rig').properties['summary']
    end

    # The hint deploys the task model: a specialization has no statement
    # of its own to write.
    def test_a_specialization_with_no_deployment
      assert_nil load_robot(<<~RUBY, 'config/robots/default.rb' => "using_task_library 'rig'\n")
        rear = OroGen.rig.Task.specialize
        rear.require_dynamic_service('export', as: 'rear')
        device(Devices::Camera, as: 'rear_cam', using: rear)
      RUBY
      assert_syskit_error(/no deployed task can run rig::Task\{1\}, the driver of device 'rear_cam'/,
                          at: 'models/profiles/base.rb:9', root: @root,
                          hint: /: Syskit.conf.use_deployment OroGen.rig.Task => 'rear_cam'\z/) { plan }
    end

    def test_with_dynamic_service_in_a_definition
      assert_nil load_robot(nil, 'models/profiles/base.rb' => <<~RUBY)
        using_task_library 'rig'
        module MyApp
          module Profiles
            profile 'Base' do
              define 'side', OroGen.rig.Task.with_dynamic_service('dimmer', as: 'side')
            end
          end
        end
      RUBY
      task = plan.find_task('rig')
      assert_equal 'rig::Task{1}', task.model
      assert_includes task.ports.map(&:name), 'side_level'
      assert_equal 1, task.properties['exports']
    end

    # A robot made alone, as Syskit's tests make one: the robot block's
    # statements, errors at the caller's line.
    def test_a_robot_definition_made_alone
      assert_nil load_robot(nil)
      rear = OroGen.rig.Task.specialize
      rear.require_dynamic_service('export', as: 'rear')
      robot = Robot::RobotDefinition.new
      device = robot.device(MyApp::Devices::Camera, as: 'rear_cam', using: rear)
      assert_equal [rear, robot], [device.using, device.robot]
      assert_equal [device], robot.each_master_device.to_a
      assert_same device, robot.rear_cam_dev
      line = __LINE__ + 1
      error = assert_raises(DeclarationError) { robot.device(MyApp::Devices::Camera, as: 'rear_cam') }
      assert_equal "#{File.expand_path(__FILE__)}:#{line}", error.location.to_s
    end

    def test_dynamic_services_are_promoted_to_submodels
      assert_nil load_robot(nil)
      task = OroGen.rig.Task
      export = task.find_dynamic_service('export')
      sub = task.new_submodel
      refute_same export, sub.find_dynamic_service('export'), 'promoted to the submodel'
      assert_same export, sub.find_dynamic_service('export').demoted
      assert_same sub.find_dynamic_service('export'), sub.find_dynamic_service('export')
      assert a_lamp_is_one_service(task, sub)
    end

    def a_lamp_is_one_service(task, sub)
      task.specialize.lamp_srv.same_service?(sub.specialize.lamp_srv)
    end

    def test_instances_required_alike_are_one_service
      assert_nil load_robot(nil)
      task = OroGen.rig.Task
      sub = task.new_submodel
      a, b, c, d = [[task, 'export', { prefix: 'p' }], [sub, 'export', { prefix: 'p' }],
                    [task, 'export', { prefix: 'q' }], [task, 'dimmer', {}]].map do |model, dynamic, options|
        model.specialize.require_dynamic_service(dynamic, as: 'x', **options)
      end
      assert_kind_of Models::BoundDynamicDataService, a
      assert a.same_service?(b), 'same dynamic service and options'
      refute a.same_service?(c), 'other options'
      refute a.same_service?(d), 'another dynamic service'
      refute a.same_service?(a.component_model.lamp_srv)
    end

    def test_an_instance_of_a_dynamic_service_the_task_does_not_have
      error = load_robot(nil, 'models/profiles/rear.rb' => <<~RUBY)
        using_task_library 'rig'
        OroGen.rig.Task.specialize.require_dynamic_service('exprot', as: 'rear')
      RUBY
      assert_reported error, /rig::Task\{1\} has no dynamic service 'exprot' to require as 'rear' \(did you mean 'ex/,
                      at: 'models/profiles/rear.rb:2', hint: /its dynamic services: dimmer, export/, root: @root
    end

    def test_require_dynamic_service_on_the_task_model_itself_changes_it
      assert_nil load_robot(nil, 'models/profiles/rear.rb' => <<~RUBY)
        using_task_library 'rig'
        OroGen.rig.Task.require_dynamic_service('export', as: 'rear')
      RUBY
      task = OroGen.rig.Task
      assert_same task, task.rear_srv.component_model
      assert_equal({ 'frame' => 'rear_frame' }, task.rear_srv.port_mappings)
      assert task.find_port('rear_frame').dynamic?
      assert_equal [task.rear_srv], task.each_required_dynamic_service.to_a
    end

    def test_a_dynamic_service_instanciates_itself_on_its_model
      assert_nil load_robot(nil)
      model = OroGen.rig.Task.specialize
      dynamic = model.find_dynamic_service('export')
      srv = dynamic.instanciate('side', prefix: 'lateral')
      assert_same srv, model.side_srv
      assert_equal({ prefix: 'lateral' }, srv.dynamic_service_options)
      assert model.find_port('lateral_frame')
      assert_raises(ArgumentError) { model.find_dynamic_service('export').instanciate('lamp') }
      assert model.each_required_dynamic_service.one?
      assert_empty OroGen.rig.Task.each_required_dynamic_service
    end

    def test_an_instance_named_like_a_service_of_another_model
      error = load_robot(nil, 'models/profiles/rear.rb' => <<~RUBY)
        using_task_library 'rig'
        OroGen.rig.Task.specialize.require_dynamic_service('export', as: 'lamp')
      RUBY
      assert_reported error, /rig::Task\{1\} already has a service 'lamp' \(MyApp::Devices::Light\), not the MyApp::Devices::Camera/,
                      at: 'models/profiles/rear.rb:2', hint: /another name/, root: @root
    end
  end

  # The same, in an app's own test, as common_models' tests write it: a
  # device of a robot made alone, driven by a specialization, stubbed,
  # deployed and configured.
  class TestRequiredDynamicServicesInAppTests < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

    APP_TEST = <<~RUBY
      using_task_library 'rig'
      module OroGen
        module Rig
          describe Task do
            it 'configures what the specialization requires' do
              model = Task.specialize
              model.require_dynamic_service('export', as: 'rear', prefix: 'back')
              robot = Syskit::Robot::RobotDefinition.new
              device = robot.device(MyApp::Devices::Camera, as: 'rear', using: model)
              task = syskit_stub_deploy_and_configure(device)
              assert_equal 1, task.properties.exports
              assert task.find_port('back_frame')
            end
          end
        end
      end
    RUBY

    def test_an_app_test_configures_a_specialization
      app = my_app(nil, TestRequiredDynamicServices::FILES.merge('test/orogen/test_rig.rb' => APP_TEST),
                   libraries: %w[rig])
      out, err, status = syskit_process('test', chdir: app)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^1 runs, 2 assertions, 0 failures, 0 errors, 0 skips$/, out)
    end
  end
end
