# frozen_string_literal: true

require 'helper'

module Syskit
  # rake conformance without a usable checkout of rock-core/tools-syskit:
  # it says what to give it. (Its counts are tested with the harness, in
  # test_self_harness.rb.)
  class TestRakeConformance < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

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
