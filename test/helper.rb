# frozen_string_literal: true

require 'minitest/autorun'
require 'syskit'
require 'syskit/cli'
require 'fileutils'
require 'stringio'
require 'tmpdir'

module Syskit
  # Helpers of the gem's own test suite.
  module SelfTest
    FIXTURES = File.expand_path('fixtures', __dir__)
    GEM_ROOT = File.expand_path('..', __dir__)

    def fixture(*path)
      File.join(FIXTURES, *path)
    end

    # Loads the app at +root+ (unloaded after the test) and fails on any
    # problem unless +problems: true+.
    def load_app(root, problems: false, **options)
      app = App.new(root)
      (@loaded_apps ||= []) << app
      app.load(**options)
      flunk "#{root} has problems:\n#{app.problems.map { |e| e.report(root) }.join("\n")}" if !problems && app.problems.any?
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

    # Runs bin/syskit in this process; returns [stdout, stderr, exit status].
    def run_cli(*args, chdir: GEM_ROOT)
      out = StringIO.new
      err = StringIO.new
      status = 0
      stdout, stderr = $stdout, $stderr
      $stdout, $stderr = out, err
      begin
        Dir.chdir(chdir) { Syskit::CLI.start(args.map(&:to_s)) }
      rescue SystemExit => e
        status = e.status
      ensure
        $stdout, $stderr = stdout, stderr
      end
      [out.string, err.string, status]
    end

    # Asserts the block raises a Syskit error reported as
    # "<at>: <message>" with a hint matching +hint+.
    def assert_syskit_error(message, at: nil, hint: nil, root: nil, klass: Syskit::Error)
      error = assert_raises(klass) { yield }
      error = error.errors.first if error.is_a?(ErrorList) && klass != ErrorList
      assert_match message, error.message
      assert_equal at, error.location&.to_s(root) if at
      assert_match hint, error.hint.to_s if hint
      error
    end

    # The problem of +app+ whose message matches +message+.
    def find_problem(app, message)
      app.problems.find { |p| p.message.match?(message) } ||
        flunk("no problem matching #{message.inspect} among:\n#{app.problems.map { |e| e.report(app.root) }.join("\n")}")
    end

    def after_teardown
      (@loaded_apps || []).reverse_each(&:unload)
      (@tmpdirs || []).each { |dir| FileUtils.rm_rf(dir) }
      super
    end
  end
end

Minitest::Test.include(Syskit::SelfTest)
