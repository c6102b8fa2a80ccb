# frozen_string_literal: true

require 'helper'

module Syskit
  # The suite's own runner (SelfTest::SuiteRunner), on a small suite run in
  # a process of its own: the test classes are shared by two processes, and
  # what the fork ran is counted, failures included, in the one summary and
  # the exit status.
  class TestSuiteRunner < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

    SUITE = <<~RUBY.freeze
      require 'minitest/autorun'
      require #{File.join(__dir__, 'suite_runner').inspect}
      Syskit::SelfTest::SuiteRunner.install

      # Each class says which process ran it, taking long enough that both
      # processes take some.
      8.times do |i|
        Class.new(Minitest::Test) do
          define_singleton_method(:name) { "Lane\#{i}" }
          define_method(:test_lane) do
            sleep 0.1
            puts "ran in \#{Process.pid}"
            assert true
          end
        end
      end

      class Failing < Minitest::Test
        def test_fails
          sleep 0.1
          flunk 'a failure to report'
        end

        # An exception Marshal cannot send (it holds a Proc).
        def test_raises
          sleep 0.1
          error = RuntimeError.new('an error holding a block')
          error.instance_variable_set(:@block, -> {})
          raise error
        end
      end
    RUBY

    def test_both_processes_run_tests_and_the_summary_counts_them_all
      out, status = run_suite
      refute status.success?, out
      assert_match(/^10 runs, 9 assertions, 1 failures, 1 errors, 0 skips$/, out)
      assert_match(/a failure to report/, out)
      assert_match(/RuntimeError: an error holding a block/, out)
      assert_equal 2, out.scan(/ran in (\d+)/).uniq.size, out
    end

    def test_without_the_fork_one_process_runs_them
      out, status = run_suite('SYSKIT_TEST_FORK' => '0')
      refute status.success?, out
      assert_match(/^10 runs, 9 assertions, 1 failures, 1 errors, 0 skips$/, out)
      assert_equal 1, out.scan(/ran in (\d+)/).uniq.size, out
    end

    def test_an_error_marshal_cannot_write_is_sent_as_what_it_was
      error = ArgumentError.new('an error holding a block')
      error.instance_variable_set(:@block, -> {})
      error.set_backtrace(['model.rb:3'])
      sent = SelfTest::ForkLane::Sender.new(nil).portable(Minitest::UnexpectedError.new(error))
      copy = Marshal.load(Marshal.dump(sent))
      assert_equal 'ArgumentError: an error holding a block', copy.error.message
      assert_equal ['model.rb:3'], copy.backtrace
    end

    private

    def run_suite(env = {})
      dir = Dir.mktmpdir('syskit-suite')
      (@tmpdirs ||= []) << dir
      File.write(File.join(dir, 'suite.rb'), SUITE)
      # In a directory of its own: a test running beside this one in the
      # suite's process may be in a directory it is about to remove.
      out, err, status = Open3.capture3(SelfTest.child_env.merge(env), RbConfig.ruby, File.join(dir, 'suite.rb'),
                                        chdir: dir, unsetenv_others: true)
      ["#{out}#{err}", status]
    end
  end
end
