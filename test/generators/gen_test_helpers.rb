# frozen_string_literal: true

require 'open3'
require 'rbconfig'

module Syskit
  # Running `syskit gen` as users do, in new apps made by `syskit gen app`
  # (the tests of test_gen*.rb).
  module GenTestHelpers
    BACKTRACE = /\.rb:\d+:in `/

    # `rake test` in the guide's app: only the empty Base profile's tests
    # fail, saying what +guide+ shows.
    def assert_shown_rake_test(app, guide)
      shown = guide.output_of('rake test').lines
      out, err, status = rake_test(app)
      refute status.success?, "#{out}\n#{err}"
      assert_equal shown.last, out.lines.grep(/ runs, /).last
      assert_equal 4, out.scan(shown[1].chomp).size, out
    end

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

    # `syskit test ARGS` (its output is the test process's).
    def syskit_test(*args, chdir:)
      syskit_process('test', *args, chdir: chdir)
    end

    # `rake test` in +app+ as a shell outside this project's Bundler runs
    # it: the app's Rakefile sets up its own Gemfile.
    def rake_test(app)
      env = (defined?(Bundler) ? Bundler.unbundled_env : ENV.to_h).except('SYSKIT_PATH', 'RUBYLIB')
      Open3.capture3(env, RbConfig.ruby, '-S', 'rake', 'test', chdir: app, unsetenv_others: true)
    end

    def assert_file(app, path, *snippets)
      text = File.read(File.join(app, path))
      snippets.each { |s| assert_includes text, s, path }
    end
  end
end
