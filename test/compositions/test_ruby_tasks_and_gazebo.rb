# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # What the Rock tutorials' compositions are made of besides task
  # contexts: components written in Ruby (Syskit::RubyTaskContext, deployed
  # with use_ruby_tasks) and the device of a simulated model
  # (use_gazebo_model).
  class TestRubyTasksAndGazebo < Minitest::Test
    include CompositionTestHelper

    GENERATOR = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          # Writes a constant speed.
          class SpeedGenerator < Syskit::RubyTaskContext
            argument :speed, default: 1.0
            output_port 'out', '/double'
            property 'period', '/double', 0.1
          end

          class Cruise < Syskit::Composition
            argument :speed
            add(SpeedGenerator, as: 'speed').with_arguments(speed: from(:parent_task).speed)
            add Devices::Wheel, as: 'wheel'
            speed_child.out_port.connect_to wheel_child.cmd_port
          end
        end
      end
    RUBY

    def test_a_ruby_task_declares_its_ports_and_is_deployed_with_use_ruby_tasks
      robot = "#{FILES['config/robots/default.rb']}require 'models/compositions/cruise'\n" \
              "Syskit.conf.use_ruby_tasks Rig::Compositions::SpeedGenerator => 'speed_setpoint'\n"
      app = load_rig({ 'models/compositions/cruise.rb' => GENERATOR, 'config/robots/default.rb' => robot },
                     profile: <<~RUBY, requires: ['models/compositions/cruise'])
                       profile 'Base' do
                       #{ROBOT.lines.map { |l| "  #{l}" }.join}
                         define 'cruise', Compositions::Cruise.use('wheel' => left_wheel_dev).with_arguments(speed: 2.0)
                       end
                     RUBY
      model = Rig::Compositions::SpeedGenerator
      assert_equal 'Rig::Compositions::SpeedGenerator', model.name
      assert_equal %w[out state], model.ports.keys.sort
      assert_equal 'Writes a constant speed.', Robot::DocComment.new.above(model.declared_at)
      plan = plan_of(app, 'cruise_def')
      task = plan.find_task('speed_setpoint')
      assert_equal ['Rig::Compositions::SpeedGenerator', { 'period' => 0.1 }], [task.model, task.properties]
      assert_equal ['speed_setpoint.out -> left_wheel.cmd'], connection_lines(plan)
    end

    def test_a_ruby_task_without_deployment_is_told_to_use_ruby_tasks
      app = load_rig({ 'models/compositions/cruise.rb' => GENERATOR },
                     profile: <<~RUBY, requires: ['models/compositions/cruise'])
                       profile 'Base' do
                       #{ROBOT.lines.map { |l| "  #{l}" }.join}
                         define 'cruise', Compositions::Cruise.use('wheel' => left_wheel_dev)
                       end
                     RUBY
      error = plan_error(app, 'cruise_def')
      assert_match(/no deployed task can run Rig::Compositions::SpeedGenerator, needed by cruise.speed/, error.message)
      assert_equal 'add to config/robots/default.rb: ' \
                   "Syskit.conf.use_ruby_tasks Rig::Compositions::SpeedGenerator => 'cruise_speed'", error.hint
    end

    def test_new_submodel_of_a_ruby_task
      load_rig
      model = RubyTaskContext.new_submodel(name: 'Generator') { output_port 'out', '/double' }
      assert_equal 'Generator', model.name
      sub = model.new_submodel
      sub.input_port 'in', '/double'
      assert_equal %w[in out state], sub.ports.keys.sort
      assert_equal %w[out state], model.ports.keys.sort
      error = assert_raises(DeclarationError) { sub.output_port 'out', '/double' }
      assert_match(/already has a port or property named 'out'/, error.message)
    end

    def test_a_ruby_task_declares_dynamic_ports
      load_rig
      model = RubyTaskContext.new_submodel do
        dynamic_input_port(/^w\w+$/, '/double')
        dynamic_output_port '^\w+$'
      end
      created = model.spec.dynamic_port_for(:input, 'wdev', Syskit.app.types.resolve('/double'))
      assert_equal :input, created.instantiate('wdev').direction
      assert_nil model.spec.dynamic_port_for(:input, 'dev', Syskit.app.types.resolve('/double'))
      assert model.spec.dynamic_port_for(:output, 'any', Syskit.app.types.resolve('/int32_t')), 'of any type'
      assert_equal %w[state], model.ports.keys, 'the state port of every task model made in Ruby'
    end

    def test_use_ruby_tasks_refuses_a_task_context_of_a_library
      robot = "#{FILES['config/robots/default.rb']}Syskit.conf.use_ruby_tasks OroGen.rig.Follower => 'x'\n"
      root = rig_app({ 'config/robots/default.rb' => robot })
      error = load_problem(root)
      assert_match(/use_ruby_tasks expects ruby task models, got rig::Follower/, error.message)
      assert_match(/use_deployment rig::Follower => 'x'/, error.hint)
    end

    # A bundle playing common_models' part: the gazebo model device and
    # the simulator's task library, in our own words.
    SIM_BUNDLE = {
      'config/syskit.yml' => "name: CommonModels\n",
      'models/devices/gazebo/root_model.rb' => <<~RUBY,
        module CommonModels
          module Devices
            module Gazebo
              device_type 'RootModel' do
                input_port 'joints_cmd', '/base/samples/Joints'
                output_port 'joints_status', '/base/samples/Joints'
              end
            end
          end
        end
      RUBY
      'models/orogen/rock_gazebo.orogen' => <<~RUBY,
        name 'rock_gazebo'
        import_types_from 'base'
        task_context 'ModelTask' do
          input_port 'joints_cmd', '/base/samples/Joints'
          output_port 'joints_samples', '/base/samples/Joints'
        end
      RUBY
      'models/orogen/rock_gazebo.rb' => <<~RUBY
        require 'common_models/models/devices/gazebo/root_model'
        Syskit.extend_model OroGen.rock_gazebo.ModelTask do
          driver_for CommonModels::Devices::Gazebo::RootModel, as: 'model', 'joints_status' => 'joints_samples'
        end
      RUBY
    }.freeze

    def test_use_gazebo_model_declares_the_device_of_the_model
      sim = write_app(SIM_BUNDLE, name: 'common_models')
      app = write_app({
                        'config/syskit.yml' => "name: Sim\nbundles: [#{sim}]\n",
                        'config/robots/default.rb' => "# the simulator runs the model's task\n",
                        'models/profiles/base.rb' => <<~RUBY
                          module Sim
                            module Profiles
                              profile 'Base' do
                                use_gazebo_model 'model://arm', prefix_device_with_name: true
                              end
                            end
                          end
                        RUBY
                      }, name: 'sim')
      loaded = load_app(app)
      device = Sim::Profiles::Base.arm_dev.device
      assert_equal ['arm', 'CommonModels::Devices::Gazebo::RootModel'], [device.name, device.model.name]
      assert_match(%r{the links, joints and sensors of model://arm}, loaded.problems.first.message)
      plan = Network::Generator.plan_profile(loaded, Sim::Profiles::Base.syskit_profile).plan
      task = plan.find_task('gazebo_arm')
      assert_equal ['rock_gazebo::ModelTask', true], [task.model, task.unmanaged]
    end

    # The simulator's task reading the model's SDF, as Rock's tutorials do.
    SDF_READER = <<~RUBY
      require 'common_models/models/devices/gazebo/root_model'
      Syskit.extend_model OroGen.rock_gazebo.ModelTask do
        driver_for CommonModels::Devices::Gazebo::RootModel, as: 'model', 'joints_status' => 'joints_samples'
        argument :robot
        def configure
          super
          properties.model_sdf = robot.sdf_model.make_root.to_xml_string
        end
      end
    RUBY

    def test_the_sdf_model_of_a_gazebo_profile_is_not_modelled
      sim = write_app(SIM_BUNDLE.merge('models/orogen/rock_gazebo.rb' => SDF_READER), name: 'common_models')
      File.write(File.join(sim, 'models/orogen/rock_gazebo.orogen'),
                 SIM_BUNDLE['models/orogen/rock_gazebo.orogen'].sub('do', "do\n  property 'model_sdf', '/std/string'"))
      app = write_app({ 'config/syskit.yml' => "name: Sim\nbundles: [#{sim}]\n", 'config/robots/default.rb' => '',
                        'models/profiles/base.rb' => <<~RUBY }, name: 'sim')
                          module Sim
                            module Profiles
                              profile 'Base' do
                                use_gazebo_model 'model://arm'
                              end
                            end
                          end
                        RUBY
      loaded = load_app(app)
      requirement = Sim::Profiles::Base.arm_dev.with_arguments(robot: Sim::Profiles::Base)
      result = Network::Generator.new(loaded, [requirement], profile: Sim::Profiles::Base.syskit_profile,
                                                             robot_config: loaded.robot_config('default')).generate
      assert_equal '', result.plan.find_task('gazebo_arm').properties['model_sdf']
      messages = loaded.problems.map(&:message)
      assert(messages.any? { |m| m.start_with?('the SDF model of Sim::Profiles::Base: not modelled') })
      assert(messages.any? { |m| m.start_with?("property 'model_sdf' of rock_gazebo::ModelTask set from something") })
    end

    # Without the simulator's models, the device use_gazebo_model would make
    # from the SDF file is not modelled: each definition that selects it,
    # or is made from one that does, is one warning at its define line and
    # is left out of the plan, rather than an error on the child left
    # without a selection. The rest of the profile is planned as before.
    CRANE = {
      'models/compositions/hoist.rb' => <<~RUBY,
        require 'models/devices/rover'
        module Rig
          module Compositions
            class Hoist < Syskit::Composition
              argument :height, default: 1
              add Devices::Wheel, as: 'winch'
            end
          end
        end
      RUBY
      'models/profiles/world.rb' => <<~RUBY,
        module Rig
          module Profiles
            profile 'World' do
              use_gazebo_model 'model://crane', prefix_device_with_name: true
              use_sdf_model 'model://hook', as: 'hook'
            end
          end
        end
      RUBY
      'models/profiles/yard.rb' => <<~RUBY
        require 'models/profiles/world'
        require 'models/compositions/hoist'
        module Rig
          module Profiles
            profile 'Yard' do
              robot { device(Devices::Wheel, as: 'spare').prefer_deployed_tasks('left_wheel') }
              use Devices::GPS => World.crane_dev
              define 'lift', Compositions::Hoist.use('winch' => World.crane_dev)
              define 'lift_high', lift_def.with_arguments(height: 10)
              define 'hook', Compositions::Hoist.use(World.hook_dev)
              define 'spare_lift', Compositions::Hoist.use('winch' => spare_dev)
            end
          end
        end
      RUBY
    }.freeze

    def test_definitions_needing_a_device_made_from_an_sdf_file_are_left_out
      loaded = load_app(rig_app(CRANE))
      yard = Rig::Profiles::Yard.syskit_profile
      assert_equal %w[spare_lift], yard.definitions.keys
      warnings = loaded.problems.select { |p| p.location&.path&.end_with?('models/profiles/yard.rb') }
      assert_equal([7, 8, 9, 10], warnings.map { |w| w.location.lineno })
      crane = %r{Rig::Profiles::World.crane_dev \(made by use_gazebo_model from the SDF file of model://crane\)}
      assert_match(/a selection of #{crane} in Rig::Profiles::Yard: not modelled/, warnings[0].message)
      assert_match(/definition 'lift', which depends on #{crane}: not modelled by this gem/, warnings[1].message)
      assert_match(/definition 'lift_high', which depends on Rig::Profiles::World.crane_dev/, warnings[2].message)
      assert_match(/definition 'hook', which depends on Rig::Profiles::World.hook_dev \(made by use_sdf_model\)/,
                   warnings[3].message)
      assert(warnings.all?(Warning))
    end

    def test_syskit_check_reports_them_as_warnings_and_no_error
      out, _, status = run_cli('check', '--app', rig_app(CRANE))
      assert_equal 0, status, out
      assert_equal 3, out.scan(/which depends on Rig::Profiles::World\.\w+_dev/).size, out
      assert_equal 1, out.scan('a selection of Rig::Profiles::World.crane_dev').size, out
      refute_match(/abstract|nothing selects/, out)
    end
  end
end
