# frozen_string_literal: true

require 'helper'
require 'minitest/mock'
require 'open3'
require 'rbconfig'

module Syskit
  # `syskit gen app|dev|bus|orogen|profile` as users run it (SPEC 10): the
  # files follow the app's conventions, load, and their tests pass.
  class TestGen < Minitest::Test
    LIB = File.join(GEM_ROOT, 'lib')
    BACKTRACE = /\.rb:\d+:in `/

    MY_LIB = <<~RUBY
      name 'my_lib'
      import_types_from 'canbus'

      task_context 'Task' do
        doc 'Reads a CAN sensor'
        property 'filter_id', 'int', 0
        output_port 'samples', '/canbus/Message'
      end

      task_context 'BusTask' do
        dynamic_output_port(/^\\w+$/, '/canbus/Message')
      end
    RUBY

    def tmpdir
      dir = Dir.mktmpdir('syskit-gen')
      (@tmpdirs ||= []) << dir
      dir
    end

    # A new app made by `syskit gen app`.
    def new_app(name = 'awesome_robot')
      dir = tmpdir
      out, err, status = run_cli('gen', 'app', name, chdir: dir)
      assert_equal 0, status, err
      [File.join(dir, name), out]
    end

    # Runs `syskit gen ARGS` successfully; returns its output.
    def gen(*args, chdir:)
      out, err, status = run_cli('gen', *args, chdir: chdir)
      assert_equal 0, status, "syskit gen #{args.join(' ')}: #{err}"
      out
    end

    # Runs `syskit gen ARGS`, expecting a refusal; returns the error output.
    def refused(*args, chdir:)
      out, err, status = run_cli('gen', *args, chdir: chdir)
      assert_equal 1, status, "syskit gen #{args.join(' ')} should be refused: #{out}"
      assert_empty out
      assert_match(/\n  hint: /, err)
      refute_match BACKTRACE, err
      err
    end

    def files_of(dir)
      Dir.glob('**/*', File::FNM_DOTMATCH, base: dir).reject { |f| f.end_with?('.') }.sort
    end

    def rake_test(app)
      Open3.capture3(RbConfig.ruby, '-I', LIB, '-S', 'rake', 'test', chdir: app)
    end

    NEW_APP = <<~TEXT.freeze
      create Gemfile
      create README.md
      create Rakefile
      create config/orogen/.gitkeep
      create config/robots/default.rb
      create config/syskit.yml
      create models/compositions/.gitkeep
      create models/devices/.gitkeep
      create models/orogen/.gitkeep
      create models/profiles/base.rb
      create models/services/.gitkeep
      create models/typekits/.gitkeep
      create test/profiles/test_base.rb
      AwesomeRobot is in awesome_robot/; next: cd awesome_robot && SYSKIT_PATH=#{GEM_ROOT} bundle exec rake test
    TEXT

    def test_a_new_app_and_every_generated_model_load_and_their_tests_pass
      app, out = new_app
      assert_equal NEW_APP, out
      generate_every_model(app)
      assert_generated_ruby(app)
      assert_generated_models(app)
      assert_generated_composition(app)
      assert_gemfile(app)

      out, err, status = run_cli('check', '--app', app)
      assert_equal [0, "AwesomeRobot: 0 error(s), 0 warning(s)\n"], [status, out], err
      out, err, status = rake_test(app)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^18 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out)
    end

    # syskit gen dev, bus, profile and orogen in +app+, from several
    # directories and with names written in several ways.
    def generate_every_model(app)
      File.write(File.join(app, 'models', 'orogen', 'my_lib.orogen'), MY_LIB)
      assert_equal "create models/devices/gps/ublox/f9.rb\ncreate test/devices/gps/ublox/test_f9.rb\n",
                   gen('dev', 'gps/ublox/f9', chdir: File.join(app, 'models'))
      assert_equal "create models/devices/camera/gig_e.rb\ncreate test/devices/camera/test_gig_e.rb\n",
                   gen('dev', 'Camera::GigE', '--app', app, chdir: tmpdir)
      assert_equal "create models/devices/bus/can.rb\ncreate test/devices/bus/test_can.rb\n",
                   gen('bus', 'can', chdir: app)
      assert_match %r{create models/devices/bus/rs485\.rb}, gen('bus', 'Bus::RS485', chdir: app)
      assert_equal "create models/profiles/live/base.rb\ncreate test/profiles/live/test_base.rb\n",
                   gen('profile', 'live/base', chdir: app)
      assert_equal "create models/orogen/my_lib.rb\ncreate test/orogen/test_my_lib.rb\n",
                   gen('orogen', 'my_lib', chdir: app)
      assert_match %r{create models/orogen/canbus\.rb}, gen('orogen', 'canbus', chdir: app)
      assert_equal "create models/services/sensing/pose.rb\ncreate test/services/sensing/test_pose.rb\n",
                   gen('srv', 'sensing/pose', chdir: app)
      assert_equal "create config/orogen/my_lib::Task.yml\n", gen('orogenconf', 'my_lib::Task', chdir: app)
      assert_equal "create models/compositions/control/arm_control.rb\n" \
                   "create test/compositions/control/test_arm_control.rb\n",
                   gen('cmp', 'control/arm_control', chdir: app)
    end

    # The composition of #generate_every_model and its test.
    def assert_generated_composition(app)
      assert_file app, 'models/compositions/control/arm_control.rb', "    module Control\n",
                  'class ArmControl < Syskit::Composition', "# add Services::Pose, as: 'pose'"
      assert_file app, 'test/compositions/control/test_arm_control.rb',
                  "require 'models/compositions/control/arm_control'", 'syskit_stub_and_deploy(ArmControl)'
    end

    # What the models generated by #generate_every_model hold.
    def assert_generated_models(app)
      assert_file app, 'models/devices/gps/ublox/f9.rb', "module GPS\n      module Ublox\n", "device_type 'F9' do"
      assert_file app, 'models/devices/camera/gig_e.rb', "module Camera\n", "device_type 'GigE' do"
      assert_file app, 'models/devices/bus/can.rb', "import_types_from 'canbus'",
                  "com_bus_type 'CAN', message_type: Types.canbus.Message do",
                  '  #   dsl_attribute :address do |address|'
      assert_file app, 'test/devices/bus/test_can.rb', "  # it 'gives attached devices an address' do"
      assert_file app, 'models/profiles/live/base.rb', "    module Live\n",
                  "      profile 'Base' do\n        robot do\n"
      assert_file app, 'test/profiles/live/test_base.rb', 'it { is_self_contained }', 'it { can_instanciate }',
                  'it { can_deploy }'
      assert_file app, 'models/orogen/my_lib.rb', "# Reads a CAN sensor\nSyskit.extend_model OroGen.my_lib.Task do",
                  'Syskit.extend_model OroGen.my_lib.BusTask do', 'create_output_port dev.name, Types.canbus.Message',
                  'properties.filter_id', 'declared in models/orogen/my_lib.orogen'
      # Syskit's shape: no require, the library at the top, the task models
      # described from inside module OroGen, each configurable.
      assert_file app, 'test/orogen/test_my_lib.rb', "using_task_library 'my_lib'\n\nmodule OroGen\n",
                  "  describe my_lib.BusTask do\n", "  describe my_lib.Task do\n", 'it { is_configurable }'
      refute_match(/require/, File.read(File.join(app, 'test', 'orogen', 'test_my_lib.rb')))
      assert_file app, 'models/orogen/canbus.rb', 'canbus.orogen, bundled with syskit'
      assert_file app, 'config/syskit.yml', "name: AwesomeRobot\n", "acronyms: [GPS, CAN, IMU]\n"
      assert_file app, 'models/services/sensing/pose.rb', "    module Sensing\n", "data_service_type 'Pose' do"
      assert_file app, 'test/services/sensing/test_pose.rb', 'assert Pose.fullfills?(Syskit::DataService)'
      assert_file app, 'config/orogen/my_lib::Task.yml',
                  "--- name:default\n# (no documentation in the spec)\nfilter_id: 0\n"
    end

    # Every generated Ruby file: magic comment, 2-space indentation, no
    # trailing spaces.
    def assert_generated_ruby(app)
      Dir[File.join(app, '{models,test,config}', '**', '*.rb'), File.join(app, '{Gemfile,Rakefile}')].each do |path|
        text = File.read(path)
        assert text.start_with?("# frozen_string_literal: true\n\n"), path
        text.lines.each_with_index do |line, i|
          assert_equal 0, line[/\A */].size % 2, "#{path}:#{i + 1}: #{line}"
          refute_match(/[ \t]$/, line, "#{path}:#{i + 1}: trailing whitespace")
        end
      end
    end

    def assert_file(app, path, *snippets)
      text = File.read(File.join(app, path))
      snippets.each { |s| assert_includes text, s, path }
    end

    # The checkout Bundler uses is the one SYSKIT_PATH names, the installed
    # version otherwise: the file names no path of the machine it was made on.
    def assert_gemfile(app)
      gemfile = File.read(File.join(app, 'Gemfile'))
      refute_match(%r{https?://|rubygems\.org|#{Regexp.escape(GEM_ROOT)}}, gemfile)
      assert_equal [:source, Gem.sources.first.uri.to_s], gemfile_calls(gemfile, {}).first
      assert_includes gemfile_calls(gemfile, 'SYSKIT_PATH' => '/src/syskit'),
                      [:gem, ['syskit'], { path: '/src/syskit' }]
      assert_includes gemfile_calls(gemfile, {}), [:gem, ['syskit', "~> #{VERSION}"], {}]
    end

    # The gem and source calls of +gemfile+ evaluated with +env+ as ENV.
    def gemfile_calls(gemfile, env)
      calls = []
      dsl = Object.new
      dsl.define_singleton_method(:source) { |uri| calls << [:source, uri] }
      dsl.define_singleton_method(:gem) { |*args, **opts| calls << [:gem, args, opts] }
      dsl.define_singleton_method(:env) { env }
      dsl.instance_eval(gemfile.gsub('ENV[', 'env['))
      calls
    end

    def test_acronyms_are_those_of_the_app
      app, = new_app('plain_bot')
      File.write(File.join(app, 'config', 'syskit.yml'), "acronyms: []\n")
      assert_match %r{create models/devices/gps/ublox/f9\.rb}, gen('dev', 'gps/ublox/f9', chdir: app)
      assert_file app, 'models/devices/gps/ublox/f9.rb', "module PlainBot\n  module Devices\n    module Gps\n"
      # A constant given as such keeps its acronym, in the same directory.
      assert_match %r{create models/devices/gps/ublox/f7\.rb}, gen('dev', 'GPS::Ublox::F7', chdir: app)
      assert_file app, 'models/devices/gps/ublox/f7.rb', "    module GPS\n"
      assert_match %r{create models/devices/bus/can\.rb}, gen('bus', 'bus/can', chdir: app)
      assert_file app, 'models/devices/bus/can.rb', "com_bus_type 'Can'"
      out, err, status = run_cli('check', '--app', app)
      assert_equal [0, "PlainBot: 0 error(s), 0 warning(s)\n"], [status, out], err
    end

    def test_refusals_write_nothing
      app, = new_app
      File.write(File.join(app, 'models', 'orogen', 'gps_ublox.orogen'),
                 "name 'gps_ublox'\ntask_context 'Task' do\nend\n")
      outside = tmpdir
      File.symlink(outside, File.join(app, 'models', 'devices', 'elsewhere'))
      before = files_of(app)

      { %w[dev 9lives] => "'9lives' is not a valid device name: '9lives' does not make a Ruby constant name",
        %w[dev gps/foo-bar] => "'gps/foo-bar' is not a valid device name: 'foo-bar' does not make",
        %w[dev /etc/gps] => "'/etc/gps' is an absolute path, a device name is not",
        %w[bus ../../can] => "'../../can' contains '..': a bus cannot leave the app's models/ and test/",
        %w[profile live/../../base] => "contains '..'",
        %w[orogen ../gps_ublox] => "contains '..'",
        %w[orogen gps/ublox] => "'gps/ublox' is not a task library name",
        %w[dev elsewhere/thing] => 'models/devices/elsewhere: this directory is a symlink out of the app',
        %w[orogen gps_ubox] => "no task library 'gps_ubox' (did you mean 'gps_ublox'?)\n  " \
                               'hint: there is no gps_ubox.orogen in models/orogen, ' }.each do |args, message|
        assert_includes refused(*args, chdir: app), message, args.join(' ')
      end
      assert_equal before, files_of(app)
      assert_empty Dir.children(outside)

      _, err, status = run_cli('gen', 'orogen', 'gps_ubox', '--trace', chdir: app)
      assert_equal 1, status
      assert_match BACKTRACE, err
    end

    def test_orogenconf_names_a_task_model_of_a_known_library
      app, = new_app
      before = files_of(app)
      assert_equal "'canbus' is not the name of a task model\n  hint: give the library and the task, as in the name " \
                   "of the configuration file: syskit gen orogenconf gps_ublox::Task\n",
                   refused('orogenconf', 'canbus', chdir: app)
      assert_equal "task library 'canbus' has no task 'canbus::Tsk' (did you mean 'canbus::Task'?)\n  " \
                   "hint: its tasks are canbus::InterfaceTask, canbus::Task\n",
                   refused('orogenconf', 'canbus::Tsk', chdir: app)
      assert_match(/\Ano task library 'canbs' \(did you mean 'canbus'\?\)\n  hint: there is no canbs.orogen/,
                   refused('orogenconf', 'canbs::Task', chdir: app))
      assert_equal before, files_of(app)
    end

    def test_errors_of_a_task_library_point_at_its_file
      app, = new_app
      File.write(File.join(app, 'models', 'orogen', 'broken.orogen'), "name 'broken'\ntask_contxt 'Task' do\nend\n")
      error = refused('orogen', 'broken', chdir: app)
      assert_match(%r{\Amodels/orogen/broken\.orogen:2: .*task_contxt}, error)
      refute File.exist?(File.join(app, 'models', 'orogen', 'broken.rb'))
    end

    def test_the_next_step_of_an_installed_syskit_is_rake_test
      dir = tmpdir
      generator = Generators::AppGenerator.new('awesome_robot', pwd: dir)
      assert_equal 'cd awesome_robot && rake test', Dir.chdir(dir) {
        generator.stub(:checkout?, false) {
          generator.next_step
        }
      }
    end

    def test_generators_run_in_an_app_only
      out_of_app = tmpdir
      assert_match(/\A#{Regexp.escape(out_of_app)} is not in a Syskit app/,
                   refused('dev', 'gps/ublox/f9', chdir: out_of_app))
      assert_match(/'nowhere' is not in a Syskit app/,
                   refused('profile', 'base', '--app', 'nowhere', chdir: out_of_app))
      assert_match(/is in the syskit gem itself, not in a Syskit app/, refused('dev', 'gps/ublox/f9', chdir: GEM_ROOT))
      assert_empty Dir.children(out_of_app)

      assert_match(/'9lives' is not a valid app name/, refused('app', '9lives', chdir: out_of_app))
      assert_match(/'foo-bar' is not a valid app name/, refused('app', 'foo-bar', chdir: out_of_app))
      assert_match(/is not a directory name relative to the current directory/,
                   refused('app', '/tmp/x', chdir: out_of_app))
      assert_match(/is not a directory name relative/, refused('app', '../x', chdir: out_of_app))
      assert_empty Dir.children(out_of_app)
    end

    # An app named after a constant that exists (Kernel, Conf...) would
    # define its modules inside it; generators refuse what check refuses.
    def test_an_app_name_that_is_taken_or_not_a_constant_is_refused
      out_of_app = tmpdir
      assert_match(/\Athe app name 'Kernel' \(from 'kernel'\) is taken: Kernel is a constant Ruby .* already defines/,
                   refused('app', 'kernel', chdir: out_of_app))
      assert_match(/\Athe app name 'Roby' \(from 'roby'\) is taken: Roby is a name Rock files use/,
                   refused('app', 'roby', chdir: out_of_app))
      assert_empty Dir.children(out_of_app)
      app, = new_app
      { "name: Conf\n" => "config/syskit.yml:1: the app name 'Conf' is taken: Conf is a name Rock files use",
        "name: 'my rover'\n" => 'config/syskit.yml:1: the app name "my rover" is not a Ruby constant name',
        "acronyms: GPS\n" => 'config/syskit.yml:1: acronyms must be a list of names' }.each do |settings, message|
        File.write(File.join(app, 'config', 'syskit.yml'), settings)
        before = files_of(app)
        assert refused('profile', 'nav/base', chdir: app).start_with?(message), settings
        assert_equal before, files_of(app)
      end
      # A directory named after a constant, without a name setting.
      kernel = File.join(tmpdir, 'kernel')
      FileUtils.mkdir_p(File.join(kernel, 'models'))
      assert_match(%r{\Aconfig/syskit.yml:1: the app name 'Kernel' \(from its directory's name\) is taken},
                   refused('dev', 'imu', chdir: kernel))
    end

    def test_existing_files_are_never_overwritten_without_force
      app, = new_app
      gen('dev', 'gps/ublox/f9', chdir: app)
      model = File.join(app, 'models/devices/gps/ublox/f9.rb')
      test = File.join(app, 'test/devices/gps/ublox/test_f9.rb')
      File.write(model, "# mine\n")
      File.delete(test)

      error = refused('dev', 'GPS::Ublox::F9', chdir: app)
      assert_equal "this file exists, nothing was written: models/devices/gps/ublox/f9.rb\n", error.lines.first
      refused('dev', 'gps/ublox/f9', '--dry-run', chdir: app)
      assert_equal "# mine\n", File.read(model)
      refute File.exist?(test)

      assert_equal "would overwrite models/devices/gps/ublox/f9.rb\nwould create test/devices/gps/ublox/test_f9.rb\n" \
                   "dry run: nothing was written\n", gen('dev', 'gps/ublox/f9', '--dry-run', '--force', chdir: app)
      assert_equal "# mine\n", File.read(model)
      refute File.exist?(test)

      assert_equal "overwrite models/devices/gps/ublox/f9.rb\ncreate test/devices/gps/ublox/test_f9.rb\n",
                   gen('dev', 'gps/ublox/f9', '--force', chdir: app)
      assert_includes File.read(model), "device_type 'F9' do"
      assert File.file?(test)
    end

    def test_a_dry_run_of_an_app_creates_nothing
      dir = tmpdir
      out = gen('app', 'awesome_robot', '--dry-run', chdir: dir)
      assert_match(%r{^would create models/profiles/base\.rb$}, out)
      assert_match(/^dry run: nothing was written$/, out)
      assert_empty Dir.children(dir)
    end

    def test_help_shows_examples
      out, = run_cli('gen', '--help')
      assert_match(%r{ gen dev TYPE/MANUFACTURER/MODEL +# create a device}, out)
      assert_match(/^Examples:\n  syskit gen app awesome_robot/, out)
      { 'app' => 'syskit gen app awesome_robot', 'dev' => 'syskit gen dev gps/ublox/f9', 'bus' => 'syskit gen bus can',
        'orogen' => 'syskit gen orogen gps_ublox', 'profile' => 'syskit gen profile live/base' }.each do |cmd, example|
        out, = run_cli('gen', 'help', cmd)
        assert_includes out, "Example: #{example}"
      end
      out, = run_cli('gen', 'dev', '--help')
      assert_includes out, 'Example: syskit gen dev gps/ublox/f9'
    end
  end
end
