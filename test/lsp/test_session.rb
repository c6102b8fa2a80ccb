# frozen_string_literal: true

require_relative '../helper'
require 'syskit/lsp'

module Syskit
  # The app session of `syskit lsp`: loaded once, checked again as far as a
  # change needs, on the editor's buffers.
  class TestLSPSession < Minitest::Test
    include SelfTest

    def setup
      @root = my_app("device(MyApp::Devices::IMU, as: 'imu').with_conf('default')",
                     'config/orogen/imu::Task.yml' => "--- name:default\nrate: 50\n",
                     'test/test_imu.rb' => "# a test\n")
      @session = LSP::Session.new(@root, log: StringIO.new)
    end

    def teardown
      @session.unload
      @other&.unload
      FileUtils.rm_rf(File.dirname(@root))
    end

    def path(relative)
      File.join(@root, relative)
    end

    def test_what_a_change_of_each_file_needs
      assert_equal :load, @session.kind_of(path('models/profiles/base.rb'))
      assert_equal :load, @session.kind_of(path('config/robots/default.rb'))
      assert_equal :load, @session.kind_of(path('models/orogen/imu.orogen'))
      assert_equal :load, @session.kind_of(path('config/syskit.yml'))
      assert_equal :conf, @session.kind_of(path('config/orogen/imu::Task.yml'))
      assert_nil @session.kind_of(path('test/test_imu.rb'))
      assert_nil @session.kind_of(path('README.md'))
      assert_nil @session.kind_of('/elsewhere/models/x.rb')
    end

    def test_a_configuration_file_is_checked_again_on_the_models_loaded
      conf = path('config/orogen/imu::Task.yml')
      assert @session.update(conf, File.read(conf))
      assert_equal [], @session.problems
      app = @session.app

      assert @session.update(conf, "--- name:default\nrat: 50\n")
      assert_same app, @session.app, 'the models are not loaded again'
      assert_equal :conf, @session.last_check.last
      problem, = @session.problems
      assert_equal Location.new(conf, 2), problem.location
      assert_match(/rat/, problem.message)
      assert_equal fresh_check_of(conf => "--- name:default\nrat: 50\n"), messages(@session.problems)

      assert @session.update(conf, File.read(conf))
      assert_equal [], @session.problems
    end

    def test_a_ruby_file_loads_the_app_again_and_an_unrelated_one_nothing
      profile = path('models/profiles/base.rb')
      text = File.read(profile)
      @session.update(profile, text)
      app = @session.app

      refute @session.update(path('test/test_imu.rb'), "# another test\n")
      refute @session.update(profile, text), 'the text checked already'
      assert_same app, @session.app

      assert @session.update(profile, text.sub('IMU,', 'IMV,'))
      refute_same app, @session.app
      assert_equal :load, @session.last_check.last
      assert_match(/IMV/, @session.problems.first.message)
      assert_equal fresh_check_of(profile => text.sub('IMU,', 'IMV,')), messages(@session.problems)
    end

    def test_a_closed_buffer_is_read_from_its_file_again
      profile = path('models/profiles/base.rb')
      @session.update(profile, File.read(profile).sub('IMU,', 'IMV,'))
      refute_empty @session.problems
      assert @session.close(profile)
      assert_equal [], @session.problems
    end

    def test_another_app_loaded_meanwhile_is_unloaded_and_this_one_loaded_again
      profile = path('models/profiles/base.rb')
      @session.update(profile, File.read(profile))
      other_root = write_app({ 'config/syskit.yml' => "name: Other\n" }, name: 'other')
      @other = LSP::Session.new(other_root, log: StringIO.new)
      @other.update(File.join(other_root, 'models', 'x.rb'), "module Other; end\n")
      assert_same @other.app, Syskit.app

      @session.with_app { |app| assert_same app, Syskit.app }
      assert_equal @root, Syskit.app.root
    end

    def test_a_bug_met_while_checking_is_a_problem_of_the_app_not_the_end_of_the_session
      log = StringIO.new
      session = LSP::Session.new(@root, log: log)
      Check.stub(:load, ->(_app) { raise NoMethodError, 'a bug' }) do
        assert session.update(path('models/profiles/base.rb'), File.read(path('models/profiles/base.rb')))
      end
      problem, = session.problems
      assert_match(/internal error of syskit while checking the app: NoMethodError: a bug/, problem.message)
      assert_match(/backtrace/, problem.hint)
      assert_match(/NoMethodError: a bug/, log.string)
    ensure
      session&.unload
    end

    def test_each_file_is_served_by_the_app_containing_it_and_none_outside_apps
      workspace = LSP::Workspace.new(log: StringIO.new)
      session = workspace.session_for(path('models/profiles/base.rb'))
      assert_equal @root, session.root
      assert_same session, workspace.session_for(path('config/orogen/imu::Task.yml'))
      outside = Dir.mktmpdir('syskit-outside')
      assert_nil workspace.session_for(File.join(outside, 'notes.rb'))
    ensure
      FileUtils.rm_rf(outside) if outside
    end

    def test_unsaved_robot_configuration_and_settings_are_checked_as_typed
      robot = path('config/robots/default.rb')
      assert @session.update(robot, "#{File.read(robot)}Syskit.conf.use_deployment OroGen.imu.Tsak => 'other'\n")
      problem, = @session.problems
      assert_equal Location.new(robot, 3), problem.location
      assert_match(/Tsak/, problem.message)
      @session.close(robot)
      assert_equal [], @session.problems

      settings = path('config/syskit.yml')
      assert @session.update(settings, "name: MyApp\nacronyms: IMU\n")
      problem, = @session.problems
      assert_equal settings, problem.location.path
      assert @session.update(settings, File.read(settings))
      assert_equal [], @session.problems
    end

    # Errors that quote the line they are at quote the buffer's.
    def test_the_line_an_error_quotes_is_the_buffer_s
      driver = path('models/orogen/imu.rb')
      @session.update(driver, "GONE = nil; require 'models/devices/imu'\nSyskit.extend_model OroGen.imu.Task do\n  " \
                              "driver_for GONE, as: 'imu'\nend\n")
      problem = @session.problems.find { |p| p.location == Location.new(driver, 3) }
      assert_match(/\AGONE is nil here/, problem&.hint)
    end

    # A file of a bundle the app uses, opened (from a definition, say): it
    # is the app's session that serves it, and checks its changes.
    def test_a_file_of_a_bundle_the_app_uses_is_served_and_checked_by_the_app
      shared, profile = app_using_a_bundle
      workspace = LSP::Workspace.new(log: StringIO.new)
      workspace.update(profile, File.read(profile)) { nil }
      session = workspace.session_for(profile)
      assert_equal [], session.problems

      assert_same session, workspace.session_for(shared)
      # An app beside it is not one of its bundles: it has its own.
      other = write_app({ 'config/syskit.yml' => "name: Other\n" }, name: 'other')
      refute_same session, workspace.session_for(File.join(other, 'models', 'x.rb'))
      assert_equal :load, session.kind_of(shared)
      assert session.update(shared, "module Shared\n  device_type 'Thing'\n  nope\nend\n")
      assert_equal [Location.new(shared, 3)], session.problems.map(&:location)
    ensure
      session&.unload
    end

    private

    # The app made to use a bundle beside it, 'shared', whose
    # models/devices/thing.rb its profile requires: that file and the
    # profile's.
    def app_using_a_bundle
      shared = File.join(File.dirname(@root), 'shared', 'models', 'devices', 'thing.rb')
      FileUtils.mkdir_p(File.dirname(shared))
      File.write(shared, "module Shared\n  device_type 'Thing'\nend\n")
      File.write(path('config/syskit.yml'), "name: MyApp\nacronyms: [IMU, CAN]\nbundles: [../shared]\n")
      profile = path('models/profiles/base.rb')
      File.write(profile, "require 'models/devices/thing'\n#{File.read(profile)}")
      [shared, profile]
    end

    # The messages of `syskit check` on the app with +buffers+ for files,
    # loaded from scratch.
    def fresh_check_of(buffers)
      @session.unload
      app = App.new(@root)
      messages(UserFile.with_buffers(buffers) { Check.new(app).run.problems })
    ensure
      app&.unload
    end

    def messages(problems)
      problems.map { |p| [p.message, p.location.to_a] }.sort
    end
  end
end
