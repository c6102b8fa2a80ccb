# frozen_string_literal: true

require 'helper'

module Syskit
  # The app of the composition tests: a rover (named Rig) with a GPS, two
  # wheels and the components that follow a path with them.
  module CompositionTestHelper
    RBS = '/base/samples/RigidBodyState'

    FILES = {
      'config/syskit.yml' => "name: Rig\nacronyms: [GPS]\n",
      'models/services/motion.rb' => <<~RUBY,
        module Rig
          module Services
            data_service_type 'Pose' do
              output_port 'pose', '#{RBS}'
            end
            data_service_type 'Odometry' do
              output_port 'odometry', '#{RBS}'
              provides Pose, 'pose' => 'odometry'
            end
            data_service_type 'SpeedCommand' do
              input_port 'speed_cmd', '/double'
            end
            data_service_type 'SpeedSource' do
              output_port 'speed_out', '/double'
            end
          end
        end
      RUBY
      'models/devices/rover.rb' => <<~RUBY,
        require 'models/services/motion'
        module Rig
          module Devices
            device_type 'GPS' do
              output_port 'position', '#{RBS}'
              provides Services::Pose, 'pose' => 'position'
            end
            device_type 'Wheel' do
              input_port 'cmd', '/double'
              output_port 'speed', '/double'
              provides Services::SpeedCommand, 'speed_cmd' => 'cmd'
            end
          end
        end
      RUBY
      'models/orogen/rig.orogen' => <<~RUBY,
        name 'rig'
        import_types_from 'base'
        task_context 'GPSDriver' do
          output_port 'position', '#{RBS}'
        end
        task_context 'WheelDriver' do
          input_port 'cmd', '/double'
          output_port 'speed', '/double'
        end
        task_context 'Follower' do
          property 'gain', '/double', 1.0
          input_port 'pose', '#{RBS}'
          output_port 'command', '/double'
        end
        task_context 'Splitter' do
          input_port 'in', '/double'
          output_port 'left', '/double'
          output_port 'right', '/double'
        end
        task_context 'Tracker' do
          output_port 'front', '#{RBS}'
          output_port 'rear', '#{RBS}'
        end
        task_context 'Logger' do
          input_port('in', '/double').multiplexes
        end
      RUBY
      'models/orogen/rig.rb' => <<~RUBY,
        require 'models/devices/rover'
        Syskit.extend_model OroGen.rig.GPSDriver do
          driver_for Rig::Devices::GPS, as: 'gps'
        end
        Syskit.extend_model OroGen.rig.WheelDriver do
          driver_for Rig::Devices::Wheel, as: 'wheel'
        end
        Syskit.extend_model OroGen.rig.Tracker do
          provides Rig::Services::Pose, as: 'front_pose', 'pose' => 'front'
          provides Rig::Services::Pose, as: 'rear_pose', 'pose' => 'rear'
        end
      RUBY
      'config/robots/default.rb' => <<~RUBY
        using_task_library 'rig'
        Syskit.conf.use_deployment OroGen.rig.GPSDriver => 'gps'
        Syskit.conf.use_deployment OroGen.rig.WheelDriver => 'left_wheel'
        Syskit.conf.use_deployment OroGen.rig.WheelDriver => 'right_wheel'
        Syskit.conf.use_deployment OroGen.rig.Follower => 'follower'
        Syskit.conf.use_deployment OroGen.rig.Splitter => 'splitter'
        Syskit.conf.use_deployment OroGen.rig.Tracker => 'tracker'
        Syskit.conf.use_deployment OroGen.rig.Logger => 'logger'
      RUBY
    }.freeze

    # The GPS and both wheels, for profiles' robot blocks.
    ROBOT = <<~RUBY
      robot do
        device Devices::GPS, as: 'gps'
        device(Devices::Wheel, as: 'left_wheel').prefer_deployed_tasks('left_wheel')
        device(Devices::Wheel, as: 'right_wheel').prefer_deployed_tasks('right_wheel')
      end
    RUBY

    # Follows the pose of a GPS (or any pose source), driving two wheels.
    FOLLOW = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          class Follow < Syskit::Composition
            argument :gain, default: 2.0
            add Services::Pose, as: 'pose'
            add OroGen.rig.Follower, as: 'follower'
            add OroGen.rig.Splitter, as: 'split'
            add Devices::Wheel, as: 'left'
            add Devices::Wheel, as: 'right'
            pose_child.pose_port.connect_to follower_child.pose_port
            follower_child.command_port.connect_to split_child.in_port
            split_child.left_port.connect_to left_child.cmd_port
            split_child.right_port.connect_to right_child.cmd_port
            export follower_child.command_port, as: 'speed'
          end
        end
      end
    RUBY

    def follow_app(profile, files = {})
      load_rig({ 'models/compositions/follow.rb' => FOLLOW }.merge(files),
               profile: profile, requires: ['models/compositions/follow'])
    end

    WHEELS = "'left' => left_wheel_dev, 'right' => right_wheel_dev"

    def connection_lines(plan)
      plan.connections.map { |c| "#{c.from.task}.#{c.from.port} -> #{c.to.task}.#{c.to.port}" }
    end

    # The app with +files+ added (a profile in models/profiles/base.rb is
    # wrapped in the Rig::Profiles module, after the requires).
    # A composition following what its abstract pose child gives, its
    # command exported as 'speed'.
    WATCH = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          class Watch < Syskit::Composition
            add Services::Pose, as: 'pose'
            add OroGen.rig.Follower, as: 'follower'
            pose_child.pose_port.connect_to follower_child.pose_port
            export follower_child.command_port, as: 'speed'
          end
        end
      end
    RUBY

    def rig_app(files = {}, profile: nil, requires: [])
      files = FILES.merge(files)
      if profile
        head = (["require 'models/devices/rover'", "using_task_library 'rig'"] +
                requires.map { |r| "require '#{r}'" }).join("\n")
        body = profile.lines.map { |l| "    #{l}" }.join
        files = files.merge('models/profiles/base.rb' => "#{head}\nmodule Rig\n  module Profiles\n#{body}  end\nend\n")
      end
      write_app(files, name: 'rig')
    end

    # Loads the app and returns it.
    # For tests of composition models made in Ruby on the loaded rig.
    module OnRig
      include CompositionTestHelper

      def setup
        super
        load_rig
      end

      # A composition model made in Ruby: +new_cmp { add ..., as: 'x' }+.
      def new_cmp(name = nil, &)
        Composition.new_submodel(name: name, &)
      end
    end

    def load_rig(files = {}, **options)
      load_app(rig_app(files, **options))
    end

    # The plan of +actions+ of Rig::Profiles::Base (every one when empty).
    def plan_of(app, *actions, robot: 'default')
      Network::Generator.plan_profile(app, Rig::Profiles::Base.syskit_profile, actions: actions, robot: robot).plan
    end

    # The generation error of +actions+ (the first of the list).
    def plan_error(app, *actions)
      error = assert_raises(Syskit::Error) { plan_of(app, *actions) }
      error.is_a?(ErrorList) ? error.errors.first : error
    end
  end
end
