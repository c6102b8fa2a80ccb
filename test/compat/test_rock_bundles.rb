# frozen_string_literal: true

require 'docs_helper'
require 'json'

module Syskit
  # Apps written as Rock's bundles are (SPEC 12): test/fixtures/rock/rover
  # uses the bundle test/fixtures/rock/base_parts, reopens task models as
  # classes, configures a bus through an operation, and has the robot
  # configurations, compositions and actions real bundles have.
  class TestRockBundles < Minitest::Test
    include SelfTest::Docs::Assertions

    ROVER = File.join(FIXTURES, 'rock', 'rover')

    def plan_json(*args)
      out, err, status = run_cli('plan', '--app', ROVER, '--format', 'json', *args)
      assert_equal 0, status, err
      JSON.parse(out)
    end

    # The rock bundles guide's example is an excerpt of what check prints.
    def test_the_guides_example
      shown = SelfTest::Docs.guide('rock-bundles').output_of('syskit check --app test/fixtures/rock/rover')
      out, err, status = run_cli('check', '--app', ROVER)
      assert_equal 0, status, err
      assert_equal 2, assert_shown_excerpt(shown, out, 'the rock bundles guide')
    end

    def test_check_accepts_the_bundle_and_warns_once_per_construct_it_does_not_model
      out, _, status = run_cli('check', '--app', ROVER)
      assert_equal 0, status, out
      warnings = out.lines.grep(/: warning: /).map { |l| l.sub(/: not modelled by this gem.*/m, '').strip }
      assert_equal [
        'models/actions/main.rb:4: warning: action interface Rover::Actions::Main',
        'models/actions/main.rb:14: warning: data monitoring table Rover::Actions::WallWatch',
        "#{File.join(FIXTURES, 'rock',
                     'base_parts')}/models/orogen/scanner.rb:10: warning: transformer in scanner::Task",
        'models/orogen/can_hub.rb:20: warning: poll in can_hub::Task',
        'models/profiles/base.rb:24: warning: use_gazebo_model in profile Rover::Profiles::Base',
        "config/robots/default.rb:4: warning: the Ruby library 'roby/schedulers/temporal' (part of Rock's runtime)",
        'config/robots/default.rb:5: warning: Roby.scheduler',
        'config/robots/sim.rb:5: warning: Syskit.conf.use_gazebo_world'
      ], warnings
      assert_match(/^Rover: 0 error\(s\), 8 warning\(s\)$/, out)
      # The hint of these warnings is said once, under the first; JSON
      # keeps it for each.
      hint = 'syskit plans devices, buses, their drivers and compositions; this has no effect on the plan'
      assert_equal ["  hint: #{hint}\n"], out.lines.grep(/hint:/)
      assert_equal 'models/actions/main.rb:4: warning: action interface Rover::Actions::Main: not modelled by this ' \
                   "gem, ignored in the plan\n", out.lines.first
      assert_match(/\A  hint: /, out.lines[1])
      json, = run_cli('check', '--app', ROVER, '--format', 'json')
      assert(JSON.parse(json)['problems'].all? { |p| p['hint'].start_with?('syskit plans devices') })
    end

    def test_the_plan_of_a_rock_style_robot
      plan = plan_json
      assert_equal(%w[battery_temp can0 front_scanner_test motor_temp], plan['tasks'].map { |t| t['name'] })
      scanner = plan['tasks'].find { |t| t['name'] == 'front_scanner_test' }
      # 'scanner_test' => 'front_' prefixes the deployment's tasks.
      assert_equal 'front_scanner_test', scanner['deployment']
      # Sections from the other bundle, enum values written as symbols; the
      # argument's default, set through orocos_task in configure.
      assert_equal({ 'max_range' => 25.0, 'mode' => 'PRECISE', 'port' => '/dev/ttyACM0' }, scanner['properties'])
      assert_equal %w[default outdoor], scanner['conf']
    end

    def test_operations_called_in_configure_are_in_the_plan_and_run_their_stub
      can0 = plan_json['tasks'].find { |t| t['name'] == 'can0' }
      names = %w[name id mask]
      assert_equal [{ 'name' => 'watch', 'arguments' => ['motor_temp', 0x210, 0x7ff], 'argument_names' => names },
                    { 'name' => 'watch', 'arguments' => ['battery_temp', 0x211, 0x7ff], 'argument_names' => names }],
                   can0['operations']
      created = can0['ports'].select { |p| p['dynamic'] }.map { |p| p['name'] }
      assert_equal %w[battery_temp motor_temp], created
      assert_equal({ 'device' => 'can0', 'deviceType' => 'SOCKET' }, can0['properties'])
      out, = run_cli('plan', '--app', ROVER)
      # Ids in hex, as the robot declares them: the spec names watch's arguments id and mask.
      assert_match(/^    operations  watch\("motor_temp", 0x210, 0x7FF\)\n {16}watch\("battery_temp", 0x211, 0x7FF\)$/,
                   out)
    end

    def test_plan_says_in_one_line_that_there_are_warnings
      _, err, status = run_cli('plan', '--app', ROVER)
      assert_equal 0, status
      assert_equal "7 warnings while loading (syskit check lists them)\n", err
    end

    # Roby's Conf: what robot configurations write, configure methods read.
    def test_conf_keeps_the_settings_written_to_it
      load_app(ROVER, robots: ['default'])
      assert_equal({ 'rover' => { 'max_speed' => 1.5 } }, ::Conf.to_h)
      assert_equal 1.5, ::Conf.rover.max_speed
      assert ::Conf.rover.max_speed?
      refute ::Conf.gazebo.use_sim_time?, 'a setting never written is false'
    end

    def test_a_robot_configuration_that_requires_another_one
      plan = plan_json('--robot', 'sim')
      assert_equal 'sim', plan['robot']
      assert_equal 4, plan['tasks'].size
    end

    # A robot file that requires itself deployed everything twice ("used
    # twice"); a second robot requiring a shared file got nothing, Ruby
    # having loaded it once already for the first.
    def test_robot_files_requiring_themselves_and_each_other
      deploy = "Syskit.conf.use_deployment OroGen.imu.Task => 'imu'\n"
      root = my_app("device(Devices::IMU, as: 'imu')\n",
                    'config/robots/default.rb' => "require_relative 'default'\n#{deploy}",
                    'config/robots/field.rb' => "require_relative './default'\n",
                    'config/robots/sim.rb' => "require 'config/robots/default'\nrequire_relative 'sim'\n")
      out, _, status = run_cli('check', '--app', root)
      assert_equal [0, "MyApp: 0 error(s), 0 warning(s)\n"], [status, out]
      %w[field sim].each do |robot|
        out, err, status = run_cli('plan', '--app', root, '--robot', robot, '--format', 'json')
        assert_equal 0, status, err
        assert_equal ['imu'], JSON.parse(out)['tasks'].map { |t| t['name'] }, robot
      end
    end

    # A robot file is compiled as a block's body (so that the compiled code
    # can be kept, see RobotConfigLoader#evaluate): it still reads as a
    # file evaluated on its own object. Its constants stay its own
    # (evaluated again for a second robot, it redefines nothing), its
    # helpers are there for it, and a return at its top level ends it.
    def test_a_robot_file_keeps_its_constants_and_may_return_early
      default = <<~RUBY
        IMU_TASK = 'imu'
        def deploy_imu
          Syskit.conf.use_deployment OroGen.imu.Task => IMU_TASK
        end
        deploy_imu
        return
        raise 'not reached'
      RUBY
      root = my_app("device(Devices::IMU, as: 'imu')\n", 'config/robots/default.rb' => default,
                                                         'config/robots/field.rb' => "require_relative './default'\n")
      out, err, status = run_cli('check', '--app', root)
      assert_equal [0, "MyApp: 0 error(s), 0 warning(s)\n", ''], [status, out, err]
      out, err, status = run_cli('plan', '--app', root, '--robot', 'field', '--format', 'json')
      assert_equal 0, status, err
      assert_equal(['imu'], JSON.parse(out)['tasks'].map { |t| t['name'] })
      refute Object.const_defined?(:IMU_TASK)
    end

    # ... and its magic comments still apply.
    def test_a_robot_file_keeps_its_magic_comments
      default = "# frozen_string_literal: true\n\nname = 'imu'\nname << '_x'\n"
      root = my_app("device(Devices::IMU, as: 'imu')\n", 'config/robots/default.rb' => default)
      out, = run_cli('check', '--app', root)
      assert_match(%r{^config/robots/default.rb:4: FrozenError}, out)
    end

    def test_robot_logs_go_to_stderr_at_the_level_syskit_log_sets
      _, err, = run_cli('plan', '--app', ROVER)
      refute_match(/Robot INFO/, err)
      with_env('SYSKIT_LOG' => 'info') do
        _, err, = run_cli('plan', '--app', ROVER)
        assert_match(/^Robot INFO: front_lidar: frames body, lidar$/, err)
      end
    end

    def test_a_reopened_task_model_is_the_model_of_extend_model
      app = load_app(ROVER)
      app.using_task_library('scanner')
      assert_same OroGen.scanner.Task, OroGen::Scanner::Task
      assert_equal ['lidar'], OroGen::Scanner::Task.driver_services.map(&:name)
      assert_equal({ range_limit: 25.0 }, OroGen::Scanner::Task.argument_defaults)
    end

    COMMON_MODELS_CAN = <<~RUBY
      import_types_from 'canbus'
      module CommonModels
        module Devices
          module Bus
            com_bus_type 'CAN', message_type: '/canbus/Message' do
              extend_attached_device_configuration do
                dsl_attribute(:can_id) { |id, mask = id| [Integer(id), Integer(mask)] }
              end
            end
          end
        end
      end
    RUBY

    COMMON_MODELS_CANBUS = <<~RUBY
      class OroGen::Canbus::Task
        driver_for CommonModels::Devices::Bus::CAN, as: 'driver'
      end
    RUBY

    # A directory of bundles holding a common_models bundle with its own CAN
    # bus model and canbus extension.
    def write_common_models
      write_app({ 'common_models/models/devices/bus/can.rb' => COMMON_MODELS_CAN,
                  'common_models/models/orogen/canbus.rb' => COMMON_MODELS_CANBUS }, name: 'bundles')
    end

    def test_the_bundled_can_model_gives_way_to_a_real_common_models_bundle
      bundles = write_common_models
      root = my_app("com_bus CommonModels::Devices::Bus::CAN, as: 'can0'\n",
                    'config/syskit.yml' => "name: MyApp\nbundles: [common_models]\n")
      with_env('SYSKIT_BUNDLE_PATH' => bundles) do
        app = load_app(root)
        bus = app.profiles.values.first.robot.find_device('can0')
        assert_equal 'CommonModels::Devices::Bus::CAN', bus.model.name
        assert_equal File.join(bundles, 'common_models', 'models', 'devices', 'bus', 'can.rb'),
                     bus.model.declared_at.path
        app.using_task_library('canbus')
        assert_equal ['driver'], OroGen.canbus.Task.driver_services.map(&:name),
                     "the gem's canbus extension gives way to the bundle's"
      end
    end

    def test_an_app_file_declaring_the_bundled_can_model_reopens_it
      root = my_app(nil, 'models/devices/bus/can.rb' => <<~RUBY)
        module CommonModels
          module Devices
            module Bus
              com_bus_type 'CAN', message_type: '/canbus/Message' do
                worstcase_processing_time 0.2
              end
            end
          end
        end
      RUBY
      app = load_app(root)
      assert_empty app.problems
      assert_equal 0.2, CommonModels::Devices::Bus::CAN.worstcase_processing_time
    end

    def test_bundles_named_by_rock_app_yml_and_register_app
      other = write_app({ 'models/services/pose.rb' => <<~RUBY }, name: 'other_bundle')
        import_types_from 'base'
        module OtherBundle
          data_service_type('Pose') { output_port 'pose', '/base/samples/RigidBodyState' }
        end
      RUBY
      for_app_yml = my_app(nil, 'config/app.yml' => "bundle:\n  dependencies:\n    - other_bundle\n",
                                'models/devices/x.rb' => "require 'other_bundle/models/services/pose'\n")
      with_env('ROCK_BUNDLE_PATH' => File.dirname(other)) do
        app = load_app(for_app_yml)
        assert_equal %w[MyApp other_bundle common_models], app.bundles.map(&:name)
        assert_kind_of Models::DataServiceModel, OtherBundle::Pose
        app.unload
      end
      for_robot = my_app(nil, 'config/robots/default.rb' => "Robot.init do\n  Roby.app.register_app '#{other}'\nend\n",
                              'models/devices/x.rb' => "require 'models/services/pose'\n")
      assert_includes load_app(for_robot).bundle_roots, other
    end

    # register_app calls are found by Ruby's parser: comments and strings
    # that mention one are not calls (a regexp over the text took them).
    def test_register_app_in_comments_and_strings_is_not_a_call
      robot = <<~RUBY
        # Roby.app.register_app '../gone_bundle'
        HELP = "write Roby.app.register_app('../some_bundle') to add one"
        =begin
        Roby.app.register_app '../older_bundle'
        =end
        Roby.app.register_app File.join(__dir__, '..', '..', '..', 'computed_bundle')
      RUBY
      root = my_app(nil, 'config/robots/default.rb' => robot)
      out, _, status = run_cli('check', '--app', root)
      assert_equal 0, status, out
      assert_equal [
        'config/robots/default.rb:6: warning: Roby.app.register_app with a path computed in Ruby: syskit reads ' \
        'bundles before robot configurations run, so this bundle is not searched',
        "  hint: write the path as a string relative to the app (register_app '../other_bundle'), or name the " \
        'bundle in config/syskit.yml: bundles: [other_bundle]',
        'MyApp: 0 error(s), 1 warning(s)'
      ], out.lines.map(&:chomp)
    end

    def test_what_rock_model_files_call_loads_with_warnings
      root = my_app(nil, 'models/orogen/imu.rb' => <<~RUBY, 'models/compositions/stack.rb' => <<~RUBY2)
        class OroGen::Imu::Task
          driver_for MyApp::Devices::IMU, as: 'imu'
          find_output_port('samples').triggered_once_per_update
          argument :origin, default: from(:planned_task).origin.of_type(Eigen::Vector3)
        end
      RUBY
        using_task_library 'imu'
        module MyApp
          class Stack < Syskit::Composition
            add OroGen.imu.Task, as: 'filter'
            ok = Syskit::Models.is_model?(Stack) && Syskit::Models.is_model?(OroGen.imu.Task) && Syskit.conf.sim? == false
            raise 'Rock helpers answer wrongly' unless ok
          end
          class Idle < Roby::Tasks::Simple; end
        end
      RUBY2
      app = load_app(root)
      app.using_task_library('imu')
      assert_empty app.errors
      assert_equal(['from in imu::Task', 'Roby task MyApp::Idle'],
                   app.problems.map { |p| p.message.sub(/: not modelled.*/, '') })
    end

    def test_a_class_statement_for_a_task_the_library_does_not_have
      root = my_app(nil, 'models/orogen/imu.rb' => "class OroGen::Imu::Taks\n  driver_for MyApp::Devices::IMU\nend\n")
      error = load_problem(root)
      assert_match(/OroGen::Imu::Taks is not a task model: the class statement made a new class/, error.message)
      assert_equal 'models/orogen/imu.rb:2', error.location.to_s(root)
      assert_match(/its task models are Task/, error.hint)
    end

    private

    def with_env(vars)
      saved = vars.keys.to_h { |k| [k, ENV.fetch(k, nil)] }
      vars.each { |k, v| ENV[k] = v }
      yield
    ensure
      saved.each { |k, v| ENV[k] = v }
    end
  end
end
