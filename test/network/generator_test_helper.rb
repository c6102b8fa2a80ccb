# frozen_string_literal: true

require 'helper'

module Syskit
  # The app of the network generation tests: a CAN bus with two sensors,
  # written by #generate with the robot block and files of each test.
  module GeneratorTestHelper
    # A demultiplexing bus driver (per-device ports both ways), a sensor
    # driver with one CAN port per direction, a writer-only driver.
    FILES = {
      'models/typekits/demux.rb' => <<~RUBY,
        struct 'Device' do
          field 'name', '/std/string'
          field 'id', '/uint32_t'
          field 'mask', '/uint32_t'
        end
      RUBY
      'models/orogen/demux.orogen' => <<~RUBY,
        name 'demux'
        import_types_from 'canbus'
        import_types_from 'demux'
        task_context 'Task' do
          property 'devices', '/std/vector</demux/Device>'
          dynamic_input_port(/^w\\w+$/, '/canbus/Message').needs_reliable_connection
          dynamic_output_port(/^\\w+$/, '/canbus/Message')
        end
      RUBY
      'models/orogen/demux.rb' => <<~RUBY,
        Syskit.extend_model OroGen.demux.Task do
          driver_for CommonModels::Devices::Bus::CAN, as: 'can'
        end
      RUBY
      'models/orogen/sensor.orogen' => <<~RUBY,
        name 'sensor'
        import_types_from 'canbus'
        import_types_from 'demux'
        task_context 'Task' do
          property 'threshold', 'double', 1.5
          property 'limits', '/demux/Device'
          input_port('can_in', '/canbus/Message').needs_reliable_connection
          output_port 'can_out', '/canbus/Message'
          worstcase_processing_time 0.05
        end
      RUBY
      'models/orogen/sensor.rb' => <<~RUBY,
        require 'models/devices/imu'
        Syskit.extend_model OroGen.sensor.Task do
          driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'
        end
      RUBY
      'config/robots/default.rb' => <<~RUBY
        using_task_library 'demux'
        using_task_library 'sensor'
        using_task_library 'imu'
        Syskit.conf.use_deployment OroGen.demux.Task => 'can0'
        Syskit.conf.use_deployment OroGen.sensor.Task => 'a'
        Syskit.conf.use_deployment OroGen.sensor.Task => 'b'
        Syskit.conf.use_deployment OroGen.imu.Task => 'imu'
      RUBY
    }.freeze

    LIBS = %w[demux sensor imu].freeze

    def generate(robot, files = {}, libraries: LIBS, actions: [], **more_files)
      root = my_app(robot, FILES.merge(files).merge(more_files), libraries: libraries)
      @root = root
      app = load_app(root)
      Network::Generator.plan_profile(app, MyApp::Profiles::Base.syskit_profile, actions: actions)
    end

    def generation_error(robot, files = {}, **options)
      error = assert_raises(Syskit::Error) { generate(robot, files, **options) }
      error.is_a?(ErrorList) ? error.errors : [error]
    end

    ON_CAN0 = <<~RUBY
      com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
      through 'can0' do
        device(Devices::TemperatureSensor, as: 'a').can_id(0x100, 0x7ff).prefer_deployed_tasks('a')%<a>s
        device(Devices::TemperatureSensor, as: 'b'%<b_opts>s).can_id(0x200, 0x7ff).prefer_deployed_tasks('b')%<b>s
      end
    RUBY

    # rubocop:disable-next Naming/MethodParameterName -- a: and b: are for the devices 'a' and 'b' of ON_CAN0
    def on_can0(a: '', b: '', b_opts: '')
      format(ON_CAN0, a: a, b: b, b_opts: b_opts)
    end
  end
end
