# frozen_string_literal: true

require 'helper'
require 'json'

module Syskit
  # Slave devices, as Syskit's device and robot-definition tests describe
  # them: services of a driver declared slave_of the service driving a
  # device are devices of their own (+cam.left+), served by the master's
  # driver task, with their actions, their place in the plan, and dynamic
  # services making slaves on demand.
  class TestSlaveDevices < Minitest::Test
    FILES = {
      'models/devices/camera.rb' => <<~RUBY,
        module MyApp
          module Devices
            device_type 'Camera' do
              output_port 'image', '/double'
            end
            device_type 'Stereo'
            data_service_type 'Clock'
          end
        end
      RUBY
      'models/orogen/stereo.orogen' => <<~RUBY,
        name 'stereo'
        task_context 'Task' do
          property 'left_period', 'double', 0
          property 'exported', 'int', 0
          output_port 'left_image', '/double'
          output_port 'right_image', '/double'
          dynamic_output_port(/^\\w+_export$/, '/double')
        end
      RUBY
      'models/orogen/stereo.rb' => <<~RUBY,
        require 'models/devices/camera'
        Syskit.extend_model OroGen.stereo.Task do
          driver_for MyApp::Devices::Stereo, as: 'stereo'
          driver_for MyApp::Devices::Camera, as: 'left', slave_of: 'stereo', 'image' => 'left_image'
          driver_for MyApp::Devices::Camera, as: 'right', slave_of: 'stereo', 'image' => 'right_image'
          provides MyApp::Devices::Clock, as: 'clock', slave_of: 'stereo'
          dynamic_service MyApp::Devices::Camera, as: 'export' do
            driver_for MyApp::Devices::Camera, 'image' => "\#{options.fetch(:prefix, name)}_export"
          end
          dynamic_service MyApp::Devices::Camera, as: 'mirror' do
            provides MyApp::Devices::Camera, as: name, slave_of: options.fetch(:of, 'stereo'),
                                             'image' => "\#{name}_export"
          end

          def configure
            super
            properties.left_period = left_dev.period || 0
            properties.exported = each_slave_device.count { |dev| dev.dynamic_service_name }
          end
        end
      RUBY
      'config/robots/default.rb' => "using_task_library 'stereo'\n" \
                                    "Syskit.conf.use_deployment OroGen.stereo.Task => 'cam'\n"
    }.freeze

    def load_robot(robot, files = {})
      @root = my_app(robot, FILES.merge(files), libraries: %w[stereo])
      @app = load_app(@root, problems: true)
      @app.problems.first
    end

    def plan(*actions)
      Network::Generator.plan_profile(@app, MyApp::Profiles::Base.syskit_profile, actions: actions).plan
    end

    def test_the_slaves_of_the_driver_are_registered_with_the_device
      assert_nil load_robot("device(Devices::Stereo, as: 'cam')\n")
      robot = MyApp::Profiles::Base.syskit_profile.robot
      cam = robot.find_device('cam')
      assert_equal %w[left right clock], cam.each_slave.map(&:name)
      left = robot.find_device('cam.left')
      assert_same left, cam.slave('left')
      assert_same left, cam.left_dev
      assert_same cam, left.master_device
      assert_equal 'cam.left', left.full_name
      assert_equal MyApp::Devices::Camera, left.model
      assert_equal OroGen.stereo.Task.find_data_service('stereo.left'), left.service
      assert_equal %w[cam.left cam.right cam.clock], robot.each_slave_device.map(&:full_name)
    end

    def test_a_slave_is_known_by_its_service_model
      load_robot("device(Devices::Stereo, as: 'cam')\n")
      left = MyApp::Profiles::Base.syskit_profile.robot.find_device('cam.left')
      assert_equal [MyApp::Devices::Camera, Syskit::Device, Syskit::DataService], left.each_fullfilled_model.to_a
      assert_equal 'left[MyApp::Devices::Camera]', left.short_name
      clock = left.master_device.slave('clock')
      assert_equal MyApp::Devices::Clock, clock.model
      assert_equal [MyApp::Devices::Clock, Syskit::DataService], clock.each_fullfilled_model.to_a
    end

    def test_slaves_have_actions_named_after_their_master
      load_robot("device(Devices::Stereo, as: 'cam')\n")
      profile = MyApp::Profiles::Base
      assert_equal %w[cam_dev cam.left_dev cam.right_dev cam.clock_dev], profile.syskit_profile.action_names
      left = profile.syskit_profile.find_action('cam.left_dev')
      assert_same left, profile.cam_dev.left_dev
      assert_equal 'cam.left', left.device.full_name
    end

    def test_a_slave_takes_the_period_burst_and_sample_size_of_its_master_unless_it_has_its_own
      load_robot(<<~RUBY)
        dev = device(Devices::Stereo, as: 'cam').period(0.1).burst(2).sample_size(3)
        dev.slave('left').period(0.05)
      RUBY
      cam = MyApp::Profiles::Base.syskit_profile.robot.find_device('cam')
      left, right = cam.each_slave.first(2)
      assert_equal [0.05, 2, 3], [left.period, left.burst, left.sample_size]
      assert_equal [0.1, 2, 3], [right.period, right.burst, right.sample_size]
    end

    def test_a_slave_the_driver_does_not_have_is_refused_where_it_is_asked_for
      error = load_robot("device(Devices::Stereo, as: 'cam')\n  .slave('lfet')\n")
      assert_reported error, /stereo::Task has no slave service 'lfet' for device 'cam' \(did you mean 'left'\?\)/,
                      at: 'models/profiles/base.rb:8', hint: /its slave services: left, right, clock/, root: @root
    end

    def test_what_configures_the_driver_is_declared_on_the_master
      error = load_robot("device(Devices::Stereo, as: 'cam').slave('left').with_conf('default')\n")
      assert_reported error, /with_conf on device 'cam.left': a slave device is served by the driver of device 'cam'/,
                      at: 'models/profiles/base.rb:7', hint: /call with_conf on cam instead/, root: @root
    end

    def test_planning_a_slave_plans_its_master_driver
      load_robot("device(Devices::Stereo, as: 'cam').slave('left').period(0.5)\n")
      plan = plan('cam.left_dev')
      assert_equal %w[cam], plan.tasks.map(&:name)
      task = plan.find_task('cam')
      assert_equal %w[cam cam.left cam.right cam.clock], task.devices
      assert_equal 0.5, task.properties['left_period']
      assert_equal %w[cam cam.clock cam.left cam.right], plan.devices.map(&:name)
      left = plan.find_device('cam.left')
      assert_equal ['MyApp::Devices::Camera', 'cam', 'cam', 0.5], left.to_h.values_at(:model, :task, :master, :period)
      assert_nil plan.find_device('cam').master
      assert_match(/^    devices     cam, cam.left, cam.right, cam.clock$/, Render::Text.render(plan))
    end

    def test_syskit_plan_takes_a_slave_action
      load_robot("device(Devices::Stereo, as: 'cam')\n")
      @loaded_apps.pop.unload
      out, err, status = run_cli('plan', 'Base', 'cam.left_dev', '--app', @root, '--format', 'json')
      assert_equal 0, status, err
      devices = JSON.parse(out)['devices'].to_h { |d| [d['name'], d['master']] }
      assert_equal({ 'cam' => nil, 'cam.clock' => 'cam', 'cam.left' => 'cam', 'cam.right' => 'cam' }, devices)
    end

    def test_a_slave_and_its_master_share_one_task
      load_robot("device(Devices::Stereo, as: 'cam')\n")
      assert_equal %w[cam], plan('cam.right_dev', 'cam_dev', 'cam.left_dev').tasks.map(&:name)
    end

    def test_lookups_of_the_master_task_find_the_slaves
      load_robot("device(Devices::Stereo, as: 'cam').slave('export', as: 'rear')\n")
      result = Network::Generator.plan_profile(@app, MyApp::Profiles::Base.syskit_profile)
      task = result.tasks.first
      cam = MyApp::Profiles::Base.syskit_profile.robot.find_device('cam')
      left = cam.slave('left')
      assert_same left, task.find_device_attached_to('stereo.left')
      assert_same left, task.left_dev
      assert_equal [OroGen.stereo.Task.find_data_service('stereo.left')], task.find_all_driver_services_for(left)
      assert_equal %w[left right clock rear], task.each_slave_device.map(&:name)
      assert_same task, result.task_for(left)
    end

    def test_a_dynamic_service_makes_slaves_with_ports_of_their_own
      load_robot(<<~RUBY)
        cam = device(Devices::Stereo, as: 'cam')
        cam.slave('export', as: 'rear')
        cam.slave('export', as: 'top', prefix: 'roof')
      RUBY
      rear = MyApp::Profiles::Base.syskit_profile.robot.find_device('cam.rear')
      assert_equal({ 'image' => 'rear_export' }, rear.service.port_mappings)
      task = plan.find_task('cam')
      assert_equal %w[cam cam.left cam.right cam.clock cam.rear cam.top], task.devices
      dynamic = task.ports.select(&:dynamic).map { |p| [p.name, p.direction, p.type] }
      assert_equal [%w[rear_export output /double], %w[roof_export output /double]], dynamic
      assert_equal 2, task.properties['exported']
    end

    # Syskit's form: provides M, as: name, slave_of: 'driver' in the block.
    def test_a_dynamic_service_block_names_the_service_its_instance_is_a_slave_of
      load_robot("device(Devices::Stereo, as: 'cam').slave('mirror', as: 'rear')\n")
      task = Network::Generator.plan_profile(@app, MyApp::Profiles::Base.syskit_profile).tasks.first
      rear = task.find_device_attached_to('stereo').slave('rear')
      assert_equal 'stereo.rear', rear.service.full_name
      assert_same rear, task.find_device_attached_to(rear.service)
      assert_equal({ 'image' => 'rear_export' }, rear.service.port_mappings)
    end

    def test_slave_of_a_service_the_task_does_not_have_in_a_dynamic_service_block
      error = load_robot("device(Devices::Stereo, as: 'cam').slave('mirror', as: 'rear', of: 'stereoo')\n")
      assert_reported error, /slave_of: 'stereoo' in dynamic service 'mirror' names no service of stereo::Task \(did /,
                      at: 'models/orogen/stereo.rb:11', hint: /its services: stereo, stereo.clock, stereo.left/,
                      root: @root
      assert_match(/did you mean 'stereo'\?/, error.message)
    end

    # As in Syskit, a device's slaves exist, bound to the driver's slave
    # services, from the device's declaration on: in the robot block,
    # before anything is generated.
    def test_slaves_are_bound_as_the_device_is_declared
      assert_nil load_robot(<<~RUBY)
        cam = device(Devices::Stereo, as: 'cam')
        cam.left_dev.period(0.05)
        clock = cam.slave('clock')
        clock.doc("\#{clock.service.full_name}: \#{clock.each_fullfilled_model.map(&:to_s).join(', ')}")
        device(Devices::Stereo, as: 'other', using: OroGen.stereo.Task).right_dev.doc('chained')
      RUBY
      robot = MyApp::Profiles::Base.syskit_profile.robot
      assert_equal 0.05, robot.find_device('cam.left').period
      assert_equal 'stereo.clock: MyApp::Devices::Clock, Syskit::DataService', robot.find_device('cam.clock').doc
      assert_equal 'chained', robot.find_device('other.right').doc
      assert_equal %w[left right clock], robot.find_device('other').each_slave.map(&:name)
    end

    def test_a_dynamic_service_the_driver_does_not_have
      error = load_robot("device(Devices::Stereo, as: 'cam').slave('exprot', as: 'rear')\n")
      assert_reported error, /stereo::Task has no dynamic service 'exprot' to make device 'cam.rear' from/,
                      at: 'models/profiles/base.rb:7', hint: /its dynamic services: export/, root: @root
    end

    def test_a_port_a_dynamic_service_cannot_create
      error = load_robot("device(Devices::Stereo, as: 'cam').slave('export', as: 'rear', prefix: 'rear-cam')\n")
      assert_reported error, /stereo::Task's port 'rear-cam_export', mapped to MyApp::Devices::Camera's output/,
                      at: 'models/orogen/stereo.rb:8', root: @root
    end
  end
end
