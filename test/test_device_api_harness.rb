# frozen_string_literal: true

require 'helper'

module Syskit
  # The device API a driver author calls in configure and in tests
  # (slave devices and their lookups, each_attached_device on a bus
  # driver), through `require 'syskit/test'` in an app, as users run it.
  class TestDeviceApiHarness < Minitest::Test
    # Processes only: run beside the in-process tests (see SelfTest::SuiteRunner).
    parallelize_me!

    def test_the_device_api_app_tests_pass
      app = fixture('device_api')
      out, err, status = syskit_process('test', '--app', app)
      assert status.success?, "#{out}\n#{err}"
      assert_match(/3 runs, \d+ assertions, 0 failures, 0 errors/, out)
    end
  end
end
