# frozen_string_literal: true

require 'helper'

module Syskit
  # A task context's transformer and stream_aligner blocks (oroGen's
  # plugins): what they declare, and the properties and ports they give
  # the task, which configuration files and connections name.
  class TestStreamPlugins < Minitest::Test
    LOCALIZER = <<~RUBY
      name 'localizer'
      import_types_from 'base'

      task_context 'Odometry' do
        input_port 'wheel_samples', '/base/samples/RigidBodyState'
        input_port 'gyro_samples', '/base/samples/RigidBodyState'
        output_port 'pose_samples', '/base/samples/RigidBodyState'
        transformer do
          max_latency 0.25
          transformation 'gyro', 'chassis'
          align_port 'wheel_samples', 0.02
          align_port 'gyro_samples', 0.01
          transform_output 'pose_samples', 'chassis' => 'odometry'
        end
      end

      task_context 'LaserOdometry' do
        subclasses 'Odometry'
        input_port 'scans', '/base/samples/RigidBodyState'
        transformer do
          align_port 'scans', 0.1
          associate_frame_to_ports 'lidar', 'scans'
        end
      end

      task_context 'Fusion' do
        input_port 'left', '/double'
        input_port 'right', '/double'
        stream_aligner do
          max_latency 0.5
          align_port 'left', 0.1
          align_port 'right'
        end
      end
    RUBY

    def localizer_app(files = {})
      my_app(nil, { 'models/orogen/localizer.orogen' => LOCALIZER,
                    'config/robots/default.rb' => "Robot.requires { using_task_library 'localizer' }\n" }
                  .merge(files))
    end

    def defaults(model)
      model.property_declarations.transform_values { |p| p.type.to_plain(p.initial_value) }
    end

    def test_a_transformer_gives_the_task_the_plugins_properties_and_ports
      load_app(localizer_app)
      odometry = OroGen.localizer.Odometry
      assert_equal({ 'transformer_max_latency' => 0.25, 'transformer_status_period' => 1.0,
                     'static_transformations' => [], 'wheel_samples_period' => 0.02,
                     'gyro_samples_period' => 0.01, 'gyro_frame' => 'gyro', 'chassis_frame' => 'chassis' },
                   defaults(odometry))
      input = odometry.spec.find_port('dynamic_transformations')
      assert_equal '/base/samples/RigidBodyState', input.type.name
      assert input.multiplexes
      assert input.reliable?
      assert input.input?
      assert_equal(%w[transformer_status transformer_stream_aligner_status],
                   %w[transformer_status transformer_stream_aligner_status].select { |n| odometry.find_output_port(n) })
      assert odometry.spec.needs_configuration
    end

    def test_a_subclass_adds_to_the_transformer_it_inherits
      load_app(localizer_app)
      laser = OroGen.localizer.LaserOdometry
      added = defaults(laser).keys - defaults(OroGen.localizer.Odometry).keys
      assert_equal ['scans_period'], added
      assert_equal %w[gyro chassis odometry lidar], laser.transformer.each_frame.to_a
      transform = laser.find_transform_of_port('pose_samples')
      assert_equal %w[chassis odometry], [transform.from, transform.to]
      assert_equal 'lidar', laser.find_frame_of_port(laser.find_input_port('scans'))
      assert_nil laser.find_frame_of_port('pose_samples')
      assert_nil OroGen.localizer.Fusion.transformer
    end

    def test_a_stream_aligner_gives_the_task_its_properties_and_status_port
      load_app(localizer_app)
      fusion = OroGen.localizer.Fusion
      assert_equal({ 'aggregator_max_latency' => 0.5, 'stream_aligner_status_period' => 1.0,
                     'left_period' => 0.1, 'right_period' => 0.0 }, defaults(fusion))
      assert fusion.find_output_port('stream_aligner_status')
    end

    def test_configuration_files_set_what_the_plugins_add
      root = localizer_app('config/orogen/localizer::LaserOdometry.yml' => <<~YAML)
        --- name:default
        chassis_frame: base_link
        scans_period: 25.ms
        transformer_max_latency: 0.5
        --- name:typo
        lidar_frame: velodyne
      YAML
      problems = load_app(root, problems: true, everything: true).problems
      assert_equal 1, problems.size, problems.map { |p| p.report(root) }.join("\n")
      # Only the frames of needed transformations are configured by name.
      assert_reported problems.first, /localizer::LaserOdometry has no property 'lidar_frame'/,
                      at: 'config/orogen/localizer::LaserOdometry.yml:6', root: root
    end

    def test_a_transformer_block_in_ruby_stays_not_modelled
      root = localizer_app('models/orogen/localizer.rb' => <<~RUBY)
        Syskit.extend_model OroGen.localizer.Odometry do
          transformer do
            frames 'map'
          end
        end
      RUBY
      app = load_app(root, problems: true)
      assert_equal(['models/orogen/localizer.rb:2: warning: transformer in localizer::Odometry: not modelled by ' \
                    'this gem, ignored in the plan'],
                   app.problems.map { |p| p.report(root).lines.first.strip })
      assert_equal %w[gyro chassis odometry], OroGen.localizer.Odometry.transformer.each_frame.to_a
    end

    def spec_error(block)
      spec = <<~RUBY
        name 'localizer'
        import_types_from 'base'
        task_context 'Task' do
          input_port 'samples', '/double'
          output_port 'pose', '/base/samples/RigidBodyState'
          transformer do
        #{block.lines.map { |l| "    #{l}" }.join}  end
        end
      RUBY
      root = localizer_app('models/orogen/localizer.orogen' => spec)
      [load_app(root, problems: true).errors.first, root]
    ensure
      @loaded_apps&.pop&.unload
    end

    def test_errors_in_a_transformer_block_are_located
      error, root = spec_error("max_latency 0.1\nalign_port 'sample', 0.1\n")
      assert_reported error, /align_port 'sample': localizer::Task has no input port 'sample' \(did you mean/,
                      at: 'models/orogen/localizer.orogen:8', hint: /its input ports are samples/, root: root
      error, root = spec_error("transform 'a', 'b'\n")
      assert_reported error, /localizer::Task's transformer block declares no max_latency/,
                      at: 'models/orogen/localizer.orogen:6', hint: /max_latency 0.1/, root: root
      error, root = spec_error("max_latency 0.1\ntransform_input 'pose', 'a' => 'b'\n")
      assert_reported error, /transform_input 'pose': localizer::Task has no input port 'pose'/,
                      at: 'models/orogen/localizer.orogen:8', root: root
      error, root = spec_error("max_latency 0.1\ntransform_output 'pose', 'body'\n")
      assert_reported error, /the transformation is one 'from' => 'to' pair, got "body"/,
                      at: 'models/orogen/localizer.orogen:8', hint: /'body' => 'world'/, root: root
    end
  end
end
