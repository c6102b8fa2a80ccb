# frozen_string_literal: true

require 'docs_helper'

module Syskit
  # `syskit test` running test files as Syskit writes them (SPEC 12):
  # test/fixtures/rock/rover/test has them in each of Syskit's forms.
  class TestRunner < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

    ROVER = File.join(FIXTURES, 'rock', 'rover')
    BACKTRACE = /\.rb:\d+:in `/

    def syskit_test(*args, chdir: GEM_ROOT)
      syskit_process('test', *args, chdir: chdir)
    end

    def test_test_files_in_syskits_forms_pass_and_runtime_tests_are_skipped_with_the_reason
      out, err, status = syskit_test('--app', ROVER, '-v')
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^16 runs, \d+ assertions, 0 failures, 0 errors, 1 skips$/, out)
      assert_match(/^syskit_deploy needs Syskit's runtime \(Roby and Orocos\)$/, out)
      assert_match(/^scanner::Task#test_0001_anonymous = [\d.]+ s = \.$/, out, 'it { is_configurable }')
    end

    def test_minitest_options_pass_through
      out, _, status = syskit_test('--app', ROVER, '-n', '/watches every/', '--seed', '42')
      assert status.success?, out
      assert_match(/--seed 42/, out)
      assert_match(/^1 runs, /, out)
      out, = syskit_test('test/orogen/test_can_hub.rb', '--exclude=/ArgumentError/', chdir: ROVER)
      assert_match(/^3 runs, /, out)
    end

    # The testing guide's command runs the test it selects, and passes.
    def test_the_guides_example
      args = SelfTest::Docs.guide('testing').text[%r{^\$ bundle exec bin/syskit test (.*)$}, 1].split
      out, err, status = syskit_test(*args)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^1 runs, \d+ assertions, 0 failures, 0 errors, 0 skips$/, out)
    end

    def test_rake_test_in_an_app_runs_its_files_as_syskit_test_does
      app = write_app({ 'Rakefile' => "require 'syskit/rake'\n",
                        'config/syskit.yml' => "name: Plain\n",
                        'test/test_plain.rb' => "describe 'a plain test' do\n  it('runs') { assert true }\nend\n" })
      out, err, status = rake_process('test', 'TESTOPTS=-v', chdir: app)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^a plain test#test_0001_runs = /, out)
    end

    def test_a_broken_test_file_is_a_located_error
      app = write_app({ 'config/syskit.yml' => "name: Plain\n",
                        'test/test_broken.rb' => "describe 'x' do\n  it 'y' do\n    assert(\n  end\nend\n",
                        'test/test_typo.rb' => "using_task_library 'canbs'\n" })
      [['test/test_broken.rb', %r{\Atest/test_broken.rb:4: syntax error}],
       ['test/test_typo.rb', %r{\Atest/test_typo.rb:1: no task library 'canbs' \(did you mean 'canbus'\?\)}]]
        .each do |file, message|
          out, err, status = syskit_test(file, chdir: app)
          assert_equal 1, status.exitstatus, out
          assert_match message, err
          refute_match BACKTRACE, err
        end
    end

    # exit in a test ended the run before minitest's report: the exit
    # status said a test failed, but not which nor why.
    def test_a_test_that_exits_fails_and_the_other_failures_are_reported
      app = write_app({ 'config/syskit.yml' => "name: Plain\n",
                        'test/test_exit.rb' => <<~RUBY,
                          describe 'a run' do
                            it('compares') { assert_equal 1, 2, 'odd' }
                            it('leaves') { exit 0 }
                          end
                        RUBY
                        'test/test_top.rb' => "exit 0\n" })
      out, err, status = syskit_test(chdir: app)
      assert_equal 1, status.exitstatus
      assert_match(%r{^a run#test_0001_compares \[test/test_exit.rb:2\]:\nodd.\nExpected: 1\n  Actual: 2$}, out)
      assert_includes out, "a run#test_0002_leaves [test/test_exit.rb:3]:\nthe test calls exit (status 0), which " \
                           'would end the run and hide the report of every test: use assertions, skip or return instead'
      # At a file's top level, the files after it would not be loaded.
      assert_match(%r{^test/test_top.rb:1: the code calls exit \(status 0\)\n  hint: }, err)
      assert_match(/^3 runs, \d+ assertions, 3 failures, 0 errors, 0 skips$/, out)
    end

    def test_a_file_that_cannot_load_fails_on_its_own_and_the_others_run
      composition = "module Plain; class Follow < Syskit::Composition; end; end\n"
      app = write_app({ 'config/syskit.yml' => "name: Plain\n", 'models/compositions/follow.rb' => composition,
                        'test/test_gem.rb' => "require 'a_gem_that_is_not_installed'\n",
                        'test/test_follow.rb' => "module Plain\n  describe(Follow) { it('runs') { flunk } }\nend\n",
                        'test/test_class.rb' => "class TestPlain < Syskit::Test::ComponentTest\n  " \
                                                "def test_it\n    assert true\n  end\nend\n" })
      out, err, status = syskit_test('-v', chdir: app)
      assert_equal 1, status.exitstatus
      assert_match(%r{^test/test_gem.rb:1: LoadError: cannot load such file -- a_gem_that_is_not_installed$}, err)
      assert_match(%r{^test/test_gem.rb \(loading\)#test_the_file_loads = [\d.]+ s = F$}, out)
      assert_match(/^Plain::Follow#test_0001_runs = [\d.]+ s = F$/, out)
      assert_match(/^TestPlain#test_it = [\d.]+ s = \.$/, out)
      assert_match(/^3 runs, \d+ assertions, 2 failures, 0 errors, 0 skips$/, out)
    end

    def test_tests_that_checked_nothing_are_named_at_their_line
      composition = "module Plain; class Follow < Syskit::Composition; end; end\n"
      app = write_app({ 'config/syskit.yml' => "name: Plain\n", 'models/compositions/follow.rb' => composition,
                        'test/test_follow.rb' => <<~RUBY })
                          module Plain
                            describe(Follow) do
                              it('checks') { assert_equal 'Plain::Follow', Follow.name }
                              it('forgets to check') { Follow.name }
                              it('waits for later') { skip 'not yet' }
                            end
                          end
                        RUBY
      out, err, status = syskit_test(chdir: app)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/^1 test\(s\) passed without checking anything \(no assertion ran\):$/, out)
      assert_match(%r{^test/test_follow.rb:4: Plain::Follow#test_0002_forgets to check$}, out)
      refute_match(/test_0001|test_0003/, out)
      assert_match(/^  hint: assert what the test expects/, out)
    end

    def test_a_failure_is_reported_at_the_line_of_the_test_and_sets_the_exit_status
      root = my_app("device(Devices::IMU, as: 'imu')\n",
                    'config/robots/default.rb' => "# nothing deployed\n",
                    'test/profiles/test_base.rb' => <<~RUBY)
                      module MyApp
                        module Profiles
                          describe Base do
                            it('deploys') { can_deploy }
                          end
                        end
                      end
                    RUBY
      out, _, status = syskit_test(chdir: root)
      assert_equal 1, status.exitstatus
      assert_match(%r{^MyApp::Profiles::Base#test_0001_deploys \[test/profiles/test_base.rb:4\]:$}, out)
      assert_match(%r{^models/profiles/base.rb:9: no deployed task can run imu::Task}, out)
    end
  end

  # What syskit test refuses before any test runs, in this process.
  class TestRunnerArguments < Minitest::Test
    ROVER = TestRunner::ROVER
    BACKTRACE = TestRunner::BACKTRACE

    def test_a_missing_file_and_an_unknown_option_are_located_errors
      _, err, status = run_cli('test', 'test/test_nothing.rb', chdir: ROVER)
      assert_equal 1, status
      assert_match(%r{\Atest/test_nothing.rb:1: no test file 'test/test_nothing.rb'\n  hint: }, err)
      _, err, status = run_cli('test', '--sede', '3', chdir: ROVER)
      assert_equal 1, status
      assert_match(/\Asyskit test does not know the option '--sede'\n  hint: minitest's options/, err)
    end

    # Values minitest would stop on with a backtrace, or an option taken
    # for a pattern, are refused before the tests start.
    def test_minitest_option_values_are_checked
      { %w[-n] => "-n needs a pattern\n  hint: e.g. syskit test -n /configure/ runs the tests whose name matches",
        %w[-e --app .] => "-e needs a pattern before '--app'\n  hint: e.g. syskit test -e /configure/ leaves out",
        %w[-s abc] => "-s takes the seed of a run, an integer, not 'abc'\n  hint: e.g. syskit test -s 42: minitest " \
                      "prints each run's seed",
        %w[--seed=x] => "--seed takes the seed of a run, an integer, not 'x'\n  hint: ",
        %w[--seed] => "--seed takes the seed of a run, an integer\n  hint: " }.each do |args, message|
        out, err, status = run_cli('test', *args, chdir: ROVER)
        assert_equal [1, ''], [status, out], args.join(' ')
        assert err.start_with?(message), "#{args.join(' ')}: #{err}"
        refute_match BACKTRACE, err
      end
    end
  end
end
