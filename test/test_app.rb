# frozen_string_literal: true

require 'helper'

module Syskit
  # Finding, naming, loading and unloading apps (SPEC 1).
  class TestApp < Minitest::Test
    def test_root_is_found_from_a_nested_directory
      root = fixture('seed', 'can_bus')
      assert_equal root, App.find_root(File.join(root, 'models', 'profiles'))
      assert_nil App.find_root('/')
    end

    def test_the_name_is_the_camelized_directory_name_unless_configured
      assert_equal 'AwesomeRobot', App.new(File.join(GEM_ROOT, 'examples', 'awesome_robot')).name
      assert_equal 'MyApp', App.new(fixture('seed', 'can_bus')).name
      root = write_app({ 'config/syskit.yml' => "acronyms: [GPS]\n" }, name: 'gps_rover')
      assert_equal 'GPSRover', App.new(root).name
    end

    def test_models_can_be_required_in_the_three_ways_the_seed_does
      root = my_app(nil, 'models/devices/a.rb' => <<~RUBY)
        require 'models/devices/imu'
        require 'devices/imu'
        require 'my_app/models/devices/imu'
      RUBY
      app = load_app(root)
      assert_equal(1, $LOADED_FEATURES.count { |f| f.end_with?('my_app/models/devices/imu.rb') })
      assert app.problems.empty?
    end

    def test_files_without_module_statements_are_evaluated_in_their_path_namespace
      root = my_app(nil, 'models/devices/imu/xsens.rb' => "device_type 'MTi'\n",
                         'models/profiles/live/rover.rb' => <<~RUBY,
                           profile 'Rover' do
                             robot { device(Devices::IMU::MTi, as: 'imu') }
                           end
                         RUBY
                         'models/orogen/imu.rb' => <<~RUBY,
                           require 'models/devices/imu'
                           Syskit.extend_model(OroGen.imu.Task) { driver_for Devices::IMU::MTi, as: 'imu' }
                         RUBY
                         'config/robots/default.rb' => "using_task_library 'imu'\n")
      load_app(root)
      assert_equal 'MyApp::Devices::IMU::MTi', MyApp::Devices::IMU::MTi.name
      assert_same MyApp::Devices::IMU::MTi, MyApp::Profiles::Live::Rover.imu_dev.device.model
    end

    def test_task_libraries_are_searched_in_the_app_then_syskit_orogen_path_then_the_gem
      shared = write_app({ 'lib/shared.orogen' => "name 'shared'\ntask_context 'Task' do\nend\n",
                           'lib/shared.rb' => "Syskit.extend_model(OroGen.shared.Task) { def from_shared_dir; end }\n",
                           'lib/canbus.orogen' => "name 'canbus'\ntask_context 'Shadowed' do\nend\n" }, name: 'shared')
      root = my_app(nil, 'models/orogen/shared.rb' => "Syskit.extend_model(OroGen.shared.Task) { def from_app; end }\n")
      app = App.new(root, orogen_path: File.join(shared, 'lib'))
      (@loaded_apps ||= []) << app
      app.load!
      assert_equal File.join(shared, 'lib', 'shared.orogen'), app.using_task_library('shared').path
      assert OroGen.shared.Task.method_defined?(:from_shared_dir)
      assert OroGen.shared.Task.method_defined?(:from_app)
      app.using_task_library('canbus')
      assert OroGen.canbus.Shadowed, 'SYSKIT_OROGEN_PATH comes before the bundled libraries'
    end

    def test_loading_a_task_library_twice_is_a_no_op
      app = load_app(my_app)
      lib = app.using_task_library('imu')
      assert_same lib, app.using_task_library('imu')
      assert_same OroGen.imu.Task, lib.find_task('Task')
      assert_equal 1, OroGen.imu.Task.services.size
    end

    def test_unload_removes_everything_the_app_defined
      load_path = $LOAD_PATH.dup
      app = App.new(fixture('seed', 'can_bus')).load!
      assert defined?(::MyApp)
      app.unload
      refute defined?(::MyApp)
      refute defined?(::OroGen)
      refute defined?(::Types)
      refute defined?(::CommonModels)
      assert_nil Syskit.app
      assert_equal load_path, $LOAD_PATH
      refute($LOADED_FEATURES.any? { |f| f.include?('fixtures/seed/can_bus') })
      # and it loads again
      load_app(fixture('seed', 'can_bus'))
      assert_equal 'can0', MyApp::Profiles::Base.can0_dev.device.name
    end

    # An unloaded app's models and types can be freed: a process that loads
    # apps one after another (a test run, syskit test) does not grow with
    # each. Ruby's method caches outlive an unloaded app: the methods the
    # bundled base typekit gives its types, and the OroGen.x methods code
    # called, must not hold the app then.
    def test_unloaded_apps_are_freed
      registries = lambda do
        3.times { GC.start }
        ObjectSpace.each_object(Types::Registry).count
      end
      before = registries.call
      5.times do
        App.new(fixture('seed', 'can_bus')).load!
        assert OroGen.canbus.Task
        Syskit.app.unload
      end
      assert_equal before, registries.call
    end

    def test_two_apps_cannot_be_loaded_at_once
      load_app(fixture('seed', 'can_bus'))
      error = assert_raises(Error) { App.new(fixture('seed', 'demux')).activate }
      assert_match(/is still loaded, unload it first/, error.message)
    end

    def test_a_syntax_error_is_reported_at_its_line
      root = my_app(nil, 'models/devices/bad.rb' => "module MyApp\n  device_type 'X' do\n    provides(\n  end\nend\n")
      error = load_problem(root)
      assert_reported error, /syntax error/, at: 'models/devices/bad.rb:4', hint: /fix the Ruby syntax/, root: root
    end

    # The robot configuration deploys a task of the library the broken
    # profile loads: one error, the syntax error, not a second one saying
    # the library is not loaded.
    def test_a_syntax_error_in_a_profile_is_the_only_error_it_causes
      profile = "using_task_library 'imu'\nmodule MyApp\n  module Profiles\n    profile('Base') do do\n  end\nend\n"
      root = my_app(nil, 'models/profiles/base.rb' => profile,
                         'config/robots/default.rb' => "Syskit.conf.use_deployment OroGen.imu.Task => 'imu'\n")
      error = load_problem(root, robots: ['default'])
      assert_reported error, /syntax error/, at: 'models/profiles/base.rb:4', root: root
    end

    # A location of a whole file (no line, or line 0 when Ruby gives none)
    # is the file's path alone, never path:0.
    def test_a_location_without_a_line_is_the_path
      assert_equal 'models/x.rb', Location.new('/app/models/x.rb', 0).to_s('/app')
      assert_equal 'models/x.rb', Location.new('/app/models/x.rb', nil).to_s('/app')
      assert_equal 'models/x.rb:3', Location.new('/app/models/x.rb', 3).to_s('/app')
    end

    def test_an_exception_raised_by_a_model_file
      root = my_app(nil, 'models/devices/bad.rb' => "module MyApp\n  raise ArgumentError, 'no way'\nend\n")
      assert_reported load_problem(root), /ArgumentError: no way/, at: 'models/devices/bad.rb:2', root: root
    end

    def test_a_misspelled_constant
      root = my_app("device(Devices::IMUU, as: 'imu')\n")
      assert_reported load_problem(root), /uninitialized constant MyApp::Devices::IMUU/,
                      at: 'models/profiles/base.rb:9', hint: /did you mean 'MyApp::Devices::IMU'\?/, root: root
    end

    def test_a_service_whose_file_is_not_required_names_the_require
      service = "module MyApp\n  module Services\n    data_service_type 'Pose'\n  end\nend\n"
      device = "module MyApp\n  module Devices\n    device_type 'Gyro' do\n      provides Services::Pose\n    " \
               "end\n  end\nend\n"
      # models/devices/ loads before models/services/: the service is not defined yet.
      root = my_app(nil, 'models/services/pose.rb' => service, 'models/devices/gyro.rb' => device)
      assert_reported load_problem(root), /uninitialized constant MyApp::Devices::Services/,
                      at: 'models/devices/gyro.rb:4',
                      hint: 'Services::Pose is defined in models/services/pose.rb, which this file does not require: ' \
                            "add require 'models/services/pose' at its top", root: root
      @loaded_apps.pop.unload
      File.write(File.join(root, 'models/devices/gyro.rb'), "require 'models/services/pose'\n#{device}")
      assert load_app(root)
    end

    def test_a_misspelled_task_library_in_the_orogen_namespace
      root = my_app("device(Devices::IMU, as: 'imu', using: OroGen.imuu.Task)\n")
      assert_reported load_problem(root),
                      /there is no task library 'imuu' \(did you mean 'imu'\?\) \(loaded: canbus, imu, temp\)/,
                      at: 'models/profiles/base.rb:9',
                      hint: /available task libraries: .*imu.*using_task_library 'name'/, root: root
    end

    def test_a_task_library_that_is_not_loaded
      root = my_app("device(Devices::IMU, as: 'imu', using: OroGen.imu.Task)\n", libraries: %w[temp])
      assert_reported load_problem(root, robots: []), /task library 'imu' is not loaded \(loaded: temp\)/,
                      at: 'models/profiles/base.rb:7', hint: /add using_task_library 'imu' before using OroGen.imu/,
                      root: root
    end

    def test_an_unknown_task_model
      root = my_app("device(Devices::IMU, as: 'imu', using: OroGen.imu.Taks)\n")
      assert_reported load_problem(root), /OroGen.imu has no 'Taks' \(did you mean 'Task'\?\)/,
                      at: 'models/profiles/base.rb:9', hint: /known under OroGen.imu: Task/, root: root
    end

    def test_an_unknown_task_library
      root = my_app(nil, 'models/profiles/x.rb' => "using_task_library 'gps_ubloxx'\n")
      assert_reported load_problem(root), /no task library 'gps_ubloxx'/,
                      at: 'models/profiles/x.rb:1',
                      hint: Regexp.new('no gps_ubloxx.orogen in models/orogen, .*models/orogen; create ' \
                                       'models/orogen/gps_ubloxx.orogen or add its directory to SYSKIT_OROGEN_PATH'),
                      root: root
    end

    def test_a_typekit_without_a_description_makes_its_types_opaque
      root = my_app(nil, 'models/devices/x.rb' => <<~RUBY)
        module MyApp
          import_types_from 'my_bus'
          module Devices
            device_type('Thing') { output_port 'out', '/my_bus/Frame' }
          end
        end
      RUBY
      app = load_app(root)
      assert_predicate app.types.find('/my_bus/Frame'), :opaque?
      assert_equal ['my_bus'], app.opaque_typekits.keys
      app.unload
      out, _, status = run_cli('check', '--app', root)
      assert_equal 0, status
      assert_match Regexp.new('^models/devices/x.rb:2: warning: typekits without a description, their types ' \
                              "taken as opaque: my_bus\n  hint: describe one in models/typekits/NAME.rb"), out
      assert_equal 1, run_cli('check', '--app', root, '--strict')[2]
    end

    def test_a_misspelled_type
      root = my_app(nil, 'models/devices/x.rb' => <<~RUBY)
        module MyApp
          import_types_from 'canbus'
          Types.canbus.Mesage
        end
      RUBY
      assert_reported load_problem(root), /Types.canbus has no 'Mesage' \(did you mean 'Message'\?\)/,
                      at: 'models/devices/x.rb:3', hint: /known under Types.canbus: .*Message/, root: root
    end

    def test_typekit_errors
      typekit = <<~RUBY
        struct 'Device' do
          field 'id', '/uint32_t'
          field 'id', '/uint8_t'
        end
      RUBY
      root = my_app(nil, 'models/typekits/my_bus.rb' => typekit,
                         'models/devices/x.rb' => "module MyApp\n  import_types_from 'my_bus'\nend\n")
      assert_reported load_problem(root), /field 'id' is declared twice/, at: 'models/typekits/my_bus.rb:3', root: root
    end

    def test_unknown_statement_in_a_typekit
      root = my_app(nil, 'models/typekits/my_bus.rb' => "strukt 'Device'\n",
                         'models/devices/x.rb' => "module MyApp\n  import_types_from 'my_bus'\nend\n")
      assert_reported load_problem(root), /unknown statement 'strukt' in a typekit file \(did you mean 'struct'\?\)/,
                      at: 'models/typekits/my_bus.rb:1', root: root
    end

    def test_syskit_conf_outside_a_robot_configuration
      root = my_app(nil, 'models/profiles/x.rb' => "Syskit.conf.sim? || Syskit.conf.use_deployment('test_canbus')\n")
      assert_reported load_problem(root), /Syskit.conf.use_deployment is only available in robot configuration files/,
                      at: 'models/profiles/x.rb:1', hint: %r{config/robots/<robot>.rb}, root: root
    end

    def test_unknown_deployment_name
      root = my_app(nil, 'config/robots/default.rb' => "Syskit.conf.use_deployment 'test_canbuss'\n")
      assert_reported load_problem(root), /no deployment named 'test_canbuss' \(did you mean 'test_canbus'\?\)/,
                      at: 'config/robots/default.rb:1', hint: /use_deployment OroGen.lib.Task => 'name'/, root: root
    end

    def test_a_deployment_is_found_without_loading_its_library_first
      root = my_app(nil, 'config/robots/default.rb' => "Syskit.conf.use_deployment 'test_canbus'\n")
      app = load_app(root)
      assert_equal ['can (canbus::Task, deployment test_canbus)'], app.robot_config.deployed_tasks.map(&:to_s)
    end

    def test_a_deployed_task_name_used_twice
      root = my_app(nil, 'config/robots/default.rb' => <<~RUBY)
        using_task_library 'imu'
        Syskit.conf.use_deployment OroGen.imu.Task => 'x'
        Syskit.conf.use_deployment OroGen.imu.Task => 'x'
      RUBY
      assert_reported load_problem(root), /deployed task name 'x' is used twice/,
                      at: 'config/robots/default.rb:3', hint: /unique on a robot/, root: root
    end

    def test_use_deployment_with_something_else
      root = my_app(nil, 'config/robots/default.rb' => "Syskit.conf.use_deployment 42\n")
      assert_reported load_problem(root), /use_deployment does not understand 42/,
                      at: 'config/robots/default.rb:1', root: root
    end

    def test_an_app_renamed_is_told_why_its_own_name_slash_models_requires_fail
      root = write_app({ 'config/syskit.yml' => "name: MyApp\n",
                         'models/devices/imu.rb' => "# the IMU\n",
                         'models/devices/a.rb' => "require 'my_app/models/devices/imu'\n" },
                       name: 'my_app_copy')
      assert_reported load_problem(root), %r{LoadError: cannot load such file -- my_app/models/devices/imu},
                      at: 'models/devices/a.rb:1', root: root,
                      hint: %r{directory is named 'my_app_copy': rename it to 'my_app', or require 'models/devices/imu'}
    end

    # A file the app's own bundle does not have: what its directory has
    # that is closest.
    def test_a_missing_file_of_the_apps_bundle_is_told_what_is_close
      files = { 'config/syskit.yml' => "name: MyApp\n", 'models/devices/imu.rb' => "# the IMU\n" }
      cases = {
        'my_app/models/devices/imus' => %r{has no models/devices/imus\.rb \(did you mean 'imu'\?\)\z},
        'my_app/models/device/imu' => %r{has no directory models/device \(did you mean 'devices'\?\)\z}
      }
      cases.each do |required, hint|
        root = write_app(files.merge('models/devices/a.rb' => "require '#{required}'\n"), name: 'my_app')
        error = assert_reported load_problem(root), /LoadError: cannot load such file -- #{required}/,
                                at: 'models/devices/a.rb:1', root: root, hint: hint
        assert_includes error.hint, "the bundle my_app (#{root})"
        @loaded_apps.pop.unload
      end
    end

    def test_a_missing_file_under_another_bundles_name_keeps_the_plain_hint
      root = write_app({ 'models/devices/a.rb' => "require 'other_bundle/models/devices/none'\n" }, name: 'my_app')
      error = load_problem(root)
      assert_match(/fix the code at this line/, error.hint)
    end

    def test_an_unknown_robot_configuration
      app = load_app(my_app)
      error = assert_raises(FileLoadError) { app.robot_config('defualt') }
      assert_match(/no configuration for robot 'defualt' \(did you mean 'default'\?\)/, error.message)
    end
  end
end
