# frozen_string_literal: true

require 'minitest/autorun'
require 'syskit'
require 'syskit/cli'
# What the commands load when they run (syskit/cli.rb loads only the
# command line): the tests use all of it.
%w[check doc render/text render/json render/dot render/svg cli/plan_files test/runner]
  .each { |path| require "syskit/#{path}" }
Syskit::CLI::Gen::GENERATORS.each { |path| require path }
require 'fileutils'
require 'open3'
require 'rbconfig'
require 'stringio'
require 'tmpdir'
require_relative 'suite_runner'

module Syskit
  # Helpers of the gem's own test suite.
  module SelfTest
    FIXTURES = File.expand_path('fixtures', __dir__)
    GEM_ROOT = File.expand_path('..', __dir__)

    # An app's file of data services that tests of services, placeholders
    # and their bindings share: Pose, Cmd, and Odometry providing Pose.
    SERVICE_FILES = {
      'models/services/things.rb' => <<~RUBY
        module MyApp
          data_service_type('Pose') { output_port 'pose', '/double' }
          data_service_type('Cmd') { input_port 'cmd', '/double' }
          data_service_type('Odometry') { provides Pose }
        end
      RUBY
    }.freeze

    # For tests of models made in Ruby (+TaskContext.new_submodel+): the
    # base app is loaded, and the models a test made are removed after it.
    module ModelsMadeInRuby
      def setup
        super
        load_app(my_app(nil), robots: [])
        @models_mark = Models.defined_models.size
      end

      def teardown
        Models.clear_defined_since(@models_mark)
        super
      end
    end

    def fixture(*path)
      File.join(FIXTURES, *path)
    end

    # Loads the app at +root+ (unloaded after the test) and fails on any
    # error (warnings are the test's to check) unless +problems: true+.
    def load_app(root, problems: false, **options)
      app = App.new(root)
      (@loaded_apps ||= []) << app
      app.load(**options)
      flunk "#{root} has problems:\n#{app.errors.map { |e| e.report(root) }.join("\n")}" if !problems && app.errors.any?
      app
    end

    # Writes +files+ (relative path => content) into a new app directory.
    def write_app(files, name: 'test_app')
      dir = File.join(Dir.mktmpdir('syskit-test'), name)
      (@tmpdirs ||= []) << File.dirname(dir)
      files.each do |path, content|
        full = File.join(dir, path)
        FileUtils.mkdir_p(File.dirname(full))
        File.write(full, content)
      end
      FileUtils.mkdir_p(File.join(dir, 'models'))
      dir
    end

    # A small app (named MyApp) with an IMU device model and its driver,
    # a CAN temperature sensor and its driver, plus +files+.
    BASE_APP = {
      'config/syskit.yml' => "name: MyApp\nacronyms: [IMU, CAN]\n",
      'models/devices/imu.rb' => <<~RUBY,
        module MyApp
          module Devices
            device_type 'IMU' do
              output_port 'samples', '/base/samples/IMUSensors'
            end
            device_type 'TemperatureSensor'
          end
        end
      RUBY
      'models/orogen/imu.orogen' => <<~RUBY,
        name 'imu'
        import_types_from 'base'
        task_context 'Task' do
          property 'device', '/std/string', '/dev/ttyUSB0'
          property 'rate', 'int', 100
          output_port 'samples', '/base/samples/IMUSensors'
        end
      RUBY
      'models/orogen/imu.rb' => <<~RUBY,
        require 'models/devices/imu'
        Syskit.extend_model OroGen.imu.Task do
          driver_for MyApp::Devices::IMU, as: 'imu'
        end
      RUBY
      'models/orogen/temp.orogen' => <<~RUBY,
        name 'temp'
        import_types_from 'canbus'
        task_context 'Task' do
          input_port('can_in', '/canbus/Message').needs_reliable_connection
          output_port 'can_out', '/canbus/Message'
        end
      RUBY
      'models/orogen/temp.rb' => <<~RUBY,
        require 'models/devices/imu'
        Syskit.extend_model OroGen.temp.Task do
          driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'
        end
      RUBY
      'config/robots/default.rb' => "using_task_library 'imu'\nSyskit.conf.use_deployment OroGen.imu.Task => 'imu'\n"
    }.freeze

    # BASE_APP with +files+, and a profile Base whose robot block is +robot+
    # (in models/profiles/base.rb, the robot block's first line is line 9).
    def my_app(robot = nil, files = {}, libraries: %w[imu temp canbus], **more_files)
      files = files.merge(more_files)
      profile = robot && <<~RUBY
        #{libraries.map { |l| "using_task_library '#{l}'" }.join("\n")}

        module MyApp
          module Profiles
            profile 'Base' do
              robot do
        #{robot.lines.map { |l| "        #{l}" }.join.chomp}
              end
            end
          end
        end
      RUBY
      write_app(BASE_APP.merge(profile ? { 'models/profiles/base.rb' => profile } : {}).merge(files), name: 'my_app')
    end

    # The single problem of loading +root+.
    def load_problem(root, **options)
      app = load_app(root, problems: true, **options)
      assert_equal 1, app.problems.size, app.problems.map { |e| e.report(root) }.join("\n")
      app.problems.first
    end

    # Asserts +error+ says +message+, at +at+ (relative to +root+), with +hint+.
    def assert_reported(error, message, at:, hint: nil, root: nil)
      assert_match message, error.message
      assert_equal at, error.location&.to_s(root)
      assert_match hint, error.hint.to_s if hint
      error
    end

    # The environment of the processes tests start: this one's without
    # Bundler's setup, which costs each Ruby process a resolution of the
    # Gemfile (0.2 s of CPU), but with the load paths of the gems this
    # process uses, so that they find the same gems.
    def self.child_env
      @child_env ||= begin
        base = defined?(Bundler) ? Bundler.unbundled_env : ENV.to_h
        paths = Gem.loaded_specs.values.flat_map(&:full_require_paths).uniq
        base.merge('RUBYLIB' => [*paths, base['RUBYLIB']].compact.join(File::PATH_SEPARATOR)).freeze
      end
    end

    # bin/syskit ARGS in a process of its own, in SelfTest.child_env with
    # +env+; returns [stdout, stderr, Process::Status].
    def syskit_process(*args, chdir: GEM_ROOT, env: {})
      Open3.capture3(SelfTest.child_env.merge(env), RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), *args,
                     chdir: chdir, unsetenv_others: true)
    end

    # `ruby ARGS` with this checkout's lib/ first (Syskit's own test files,
    # run as a Syskit developer runs them).
    def ruby_process(*args, chdir:, env: {})
      Open3.capture3(SelfTest.child_env.merge(env), RbConfig.ruby, '-I', File.join(GEM_ROOT, 'lib'), *args,
                     chdir: chdir, unsetenv_others: true)
    end

    # Writes +content+ as test/NAME under +dir+; returns its path.
    def write_self_test(dir, name, content)
      path = File.join(dir, 'test', name)
      FileUtils.mkdir_p(File.dirname(path))
      File.write(path, content)
      path
    end

    # `rake ARGS` with this checkout's lib/ first, as tests of apps run it.
    def rake_process(*args, chdir:)
      Open3.capture3(SelfTest.child_env, RbConfig.ruby, '-I', File.join(GEM_ROOT, 'lib'), '-S', 'rake', *args,
                     chdir: chdir, unsetenv_others: true)
    end

    # Runs bin/syskit in this process; returns [stdout, stderr, exit status].
    def run_cli(*args, chdir: GEM_ROOT)
      out = StringIO.new
      err = StringIO.new
      status = 0
      stdout = $stdout
      stderr = $stderr
      $stdout = out
      $stderr = err
      begin
        Dir.chdir(chdir) { Syskit::CLI.start(args.map(&:to_s)) }
      rescue SystemExit => e
        status = e.status
      ensure
        $stdout = stdout
        $stderr = stderr
      end
      [out.string, err.string, status]
    end

    # Asserts the block raises a Syskit error reported as
    # "<at>: <message>" with a hint matching +hint+.
    def assert_syskit_error(message, at: nil, hint: nil, root: nil, klass: Syskit::Error, &block)
      error = assert_raises(klass, &block)
      error = error.errors.first if error.is_a?(ErrorList) && klass != ErrorList
      assert_match message, error.message
      assert_equal at, error.location&.to_s(root) if at
      assert_match hint, error.hint.to_s if hint
      error
    end

    # The problem of +app+ whose message matches +message+.
    def find_problem(app, message)
      found = app.problems.find { |p| p.message.match?(message) }
      return found if found

      flunk("no problem matching #{message.inspect} among:\n#{app.problems.map { |e| e.report(app.root) }.join("\n")}")
    end

    def after_teardown
      (@loaded_apps || []).reverse_each(&:unload)
      (@tmpdirs || []).each { |dir| FileUtils.rm_rf(dir) }
      super
      checked_nothing if passed? && assertions.zero?
    end

    # A test that passes without a single assertion checked nothing (a
    # `flunk ... if` that never ran, a loop over an empty list): it fails,
    # so that such a test is seen and fixed.
    def checked_nothing
      failures << Minitest::Assertion.new("#{self.class}##{name} passed without checking anything (no assertion)")
    end
  end
end

Minitest::Test.include(Syskit::SelfTest)

Syskit::SelfTest::SuiteRunner.install
# Computed before any test runs, from the environment the suite started in.
Syskit::SelfTest.child_env
