# frozen_string_literal: true

require 'helper'
require 'open3'
require_relative 'test_self_harness' # its SELF_TEST file

module Syskit
  # `rake conformance`: Syskit's own test files run from a checkout of
  # rock-core/tools-syskit, file by file.
  class TestConformanceTask < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

    def test_rake_conformance_counts_each_file_of_a_checkout
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'models/test_shape.rb', TestSelfHarness::SELF_TEST)
        write_self_test(dir, 'robot/test_broken.rb', "require 'syskit/test/self'\nSyskit::NoSuchThing\n")
        out, err, status = Open3.capture3(
          SelfTest.child_env.merge('SYSKIT_SOURCE' => dir, 'CASES' => File.join(dir, 'none.tsv')),
          RbConfig.ruby, '-S', 'rake', 'conformance', chdir: GEM_ROOT, unsetenv_others: true
        )
        assert status.success?, "#{out}\n#{err}"
        assert_match(%r{^test/models/test_shape.rb\s+5\s+1\s+0\s+1\s+1\s}, out)
        assert_match(%r{^test/robot/test_broken.rb\s+0\s+0\s+0\s+0\s+0\s+does not load: .*NoSuchThing}, out)
        assert_match(/^total \(2 files, 1 not loading\)\s+5\s+1\s+0\s+1\s+1/, out)
      end
    end

    def test_rake_conformance_refuses_a_directory_that_is_not_a_checkout
      Dir.mktmpdir do |dir|
        out, err, status = Open3.capture3(SelfTest.child_env.merge('SYSKIT_SOURCE' => dir), RbConfig.ruby, '-S',
                                          'rake', 'conformance', chdir: GEM_ROOT, unsetenv_others: true)
        refute status.success?, out
        assert_match(%r{rake conformance: #{Regexp.escape(dir)} is not a checkout of rock-core/tools-syskit}, err)
        assert_match(%r{\(no test/models/ in it\)}, err)
      end
    end

    def test_rake_conformance_without_a_checkout_says_how_to_give_one
      out, err, status = Open3.capture3(SelfTest.child_env, RbConfig.ruby, '-S', 'rake', 'conformance',
                                        chdir: GEM_ROOT, unsetenv_others: true)
      assert status.success?, err
      assert_match(%r{skipped, no checkout of rock-core/tools-syskit given \(SYSKIT_SOURCE=DIR}, out)
    end
  end
end
