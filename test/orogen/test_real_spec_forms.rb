# frozen_string_literal: true

require 'helper'

module Syskit
  # The statements and type forms of real driver packages' .orogen files
  # (SPEC 12), each in a spec written for this test.
  class TestRealSpecForms < Minitest::Test
    SONAR_SPEC = <<~'RUBY'
      name 'sonar'
      version '1.2'
      cxx_standard 'c++17'
      self.define_default_deployments = false
      using_library 'sonar_driver', typekit: false
      import_types_from 'base'
      import_types_from 'gps_base'
      import_types_from 'sonar/Config.hpp'

      typekit do
        export_types '/sonar/Config'
        remove_types '/sonar/Internal'
      end
      typekit.export_types '/sonar/Beam'

      OroGen::Spec::Deployment.register_global_initializer(:sonar)

      task_context 'Task' do
        needs_configuration
        property 'config', 'sonar::Config'
        property 'gains', 'std::vector<double>'
        property 'enabled', 'bool', 0
        property 'speed_of_sound', '/double', 1500.0
        property 'counts', 'int[4]'
        property 'origin', '/std/vector</gps_base/Solution>'
        property 'timeout', '/base/Time'
        find_property('timeout').dynamic
        output_port 'beam', 'sonar::Beam'
        output_port 'frame', ro_ptr('/base/samples/frame/Frame')
        output_port 'poses', 'std::vector<base::samples::RigidBodyState>'
        operation('set_gain').arg('gain', 'double').returns('bool')
        periodic(0.1).doc('every 100 ms')
      end

      task_context 'Recorder' do
        dynamic_input_port(/\w+\.\w+/, nil).needs_reliable_connection.task_trigger
        input_port 'pings', '/double'
        transformer do
          max_latency 0.1
          transform 'sonar', 'hull'
          align_port 'pings', 0.05
        end
        find_property('transformer_max_latency').dynamic
      end

      simple_deployment 'sonar_test', 'sonar::Task'

      deployment 'sonar_logged' do
        task 'sonar', 'sonar::Task'
        task 'sonar_logger', 'logger::Logger'
      end
    RUBY

    def load_sonar
      app = load_app(my_app(nil, 'models/orogen/sonar.orogen' => SONAR_SPEC))
      app.using_task_library('sonar')
      app
    end

    def test_the_types_of_a_spec_written_as_real_packages_write_them
      load_sonar
      task = OroGen.sonar.Task
      types = task.property_declarations.transform_values { |p| p.type.name }
      assert_equal({ 'config' => '/sonar/Config', 'gains' => '/std/vector</double>', 'enabled' => '/bool',
                     'speed_of_sound' => '/double', 'counts' => '/int32_t[4]',
                     'origin' => '/std/vector</gps_base/Solution>', 'timeout' => '/base/Time' }, types)
      assert_equal false, task.property_declarations['enabled'].initial_value
      assert_equal '/RTT/extras/ReadOnlyPointer</base/samples/frame/Frame>', task.find_port('frame').type.name
      assert_equal '/std/vector</base/samples/RigidBodyState>', task.find_port('poses').type.name
    end

    def test_the_statements_of_a_spec_written_as_real_packages_write_them
      app = load_sonar
      assert_equal [%w[gain double]], OroGen.sonar.Task.operations['set_gain'].arguments
      deployed = app.orogen.find_deployment('sonar_test').task_activities.map { |t| [t.name, t.model.name] }
      assert_equal [%w[sonar_test sonar::Task]], deployed
      assert_equal 'logger::Logger', app.orogen.find_deployment('sonar_logged').task_activities.last.model.name
    end

    def test_dynamic_ports_of_any_type_and_what_plugins_add
      load_sonar
      pattern = OroGen.sonar.Recorder.dynamic_ports.first
      assert_nil pattern.type
      assert pattern.match?('gps.pose', OroGen.sonar.Task.find_port('beam').type)
      assert_equal 'dynamic input port /\\w+\\.\\w+/ (any type)', pattern.to_s
      # What the transformer block adds, with the defaults it declares.
      recorder = OroGen.sonar.Recorder
      defaults = recorder.property_declarations.transform_values(&:initial_value)
      assert_equal({ 'transformer_max_latency' => 0.1, 'pings_period' => 0.05, 'sonar_frame' => 'sonar',
                     'hull_frame' => 'hull', 'transformer_status_period' => 1.0, 'static_transformations' => [] },
                   defaults)
      assert recorder.find_input_port('dynamic_transformations')
      assert recorder.find_output_port('transformer_status')
      assert_equal %w[sonar hull], recorder.transformer.each_frame.to_a
    end

    def test_calls_on_orogen_spec_are_a_warning
      app = load_sonar
      reports = app.problems.map { |p| p.report(app.root).lines.first.strip }
      assert_equal ['models/orogen/sonar.orogen:16: warning: OroGen::Spec::Deployment.register_global_initializer: ' \
                    'not modelled by this gem, ignored in the plan'], reports
    end

    # A spec that looks its C++ library up among the build machine's
    # pkg-config packages, and sets its types' build metadata.
    def test_a_pkg_config_look_up_is_a_warning_and_the_spec_loads
      root = my_app(nil, 'models/orogen/mesh.orogen' => <<~RUBY)
        name 'mesh'
        mesh_lib = Utilrb::PkgConfig.each_package.find { |pkg| /^libmesh/.match(pkg) }
        raise 'no libmesh package' unless mesh_lib
        using_library mesh_lib

        import_types_from 'mesh/Mesh.hpp'
        typekit do
          find_type('/mesh/Mesh').metadata.set('orogen_include', 'mesh:mesh/Mesh.hpp')
          export_types '/mesh/Mesh'
        end
        task_context('Simplifier') { property 'ratio', '/double', 0.5 }
      RUBY
      app = load_app(root)
      app.using_task_library('mesh')
      assert OroGen.mesh.Simplifier
      assert_equal(['models/orogen/mesh.orogen:2: warning: Utilrb::PkgConfig.each_package: not modelled by this gem, ' \
                    'ignored in the plan'], app.problems.map { |p| p.report(root).lines.first.strip })
    end

    def test_a_vector_of_a_base_type_resolves_whatever_was_seen_before
      app = load_app(my_app(nil, 'models/devices/x.rb' => <<~RUBY))
        module MyApp
          data_service_type('Poses') { output_port 'poses', '/std/vector</base/samples/RigidBodyState>' }
          data_service_type('Frames') { output_port 'frame', ro_ptr('/base/samples/frame/Frame') }
        end
      RUBY
      assert_same app.types.find('/base/samples/RigidBodyState'), MyApp::Poses.ports['poses'].type.element
      assert_equal '/RTT/extras/ReadOnlyPointer</base/samples/frame/Frame>', MyApp::Frames.ports['frame'].type.name
    end

    def test_numeric_aliases_with_or_without_a_slash
      app = load_app(my_app)
      %w[int /int int32_t /int32_t].each { |name| assert_equal '/int32_t', app.types.find(name).name }
      assert_equal '/std/vector</std/string>', app.types.find('/std::vector</std::string>').name
      assert_equal '/std/vector</double>', app.types.find('/std/vector</double').name, "oroGen accepts a missing '>'"
    end

    # A robot that deploys a simple_deployment finds its library as it
    # finds a deployment block's (it was "no deployment named"); when the
    # library does not load, its error is the only one.
    def test_a_simple_deployment_is_found_before_its_library_is_loaded
      robot = "Syskit.conf.use_deployment 'sonar_test'\n"
      root = my_app(nil, 'models/orogen/sonar.orogen' => SONAR_SPEC, 'config/robots/default.rb' => robot)
      out, _, status = run_cli('check', '--app', root)
      assert_equal 0, status, out
      File.write(File.join(root, 'models', 'orogen', 'sonar.orogen'),
                 "name 'sonar'\ntask_context 'Task' do\nend\nsimple_deployment 'sonar_test', 'Taks'\n")
      out, _, status = run_cli('check', '--app', root)
      assert_equal 1, status
      assert_equal ["models/orogen/sonar.orogen:4: unknown task model 'Taks'",
                    '  hint: the task models known here are sonar::Task', 'MyApp: 1 error(s), 0 warning(s)'],
                   out.lines.map(&:chomp)
      # Asked for by the robot configuration too, the library's error is
      # still one error (plan printed it three times).
      File.write(File.join(root, 'config', 'robots', 'default.rb'), "using_task_library 'sonar'\n#{robot}")
      _, err, status = run_cli('plan', '--app', root)
      assert_equal [1, "models/orogen/sonar.orogen:4: unknown task model 'Taks'\n  hint: the task models known here " \
                       "are sonar::Task\n"], [status, err]
    end

    def test_an_unknown_statement_is_still_a_located_error
      root = my_app(nil, 'models/orogen/sonar.orogen' => "name 'sonar'\ntask_context 'Task' do\n  sampling 10\nend\n")
      app = load_app(root)
      error = assert_raises(SpecError) { app.using_task_library('sonar') }
      assert_reported(error, /unknown statement 'sampling' in task_context 'Task'/,
                      at: 'models/orogen/sonar.orogen:3', root: root)
    end
  end
end
