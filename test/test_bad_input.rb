# frozen_string_literal: true

require 'helper'
require 'open3'
require 'rbconfig'
require 'timeout'

module Syskit
  # Bad input the broken-app corpus cannot hold in git (FIFOs, signals),
  # and input that only looks bad (a byte-order mark).
  class TestBadInput < Minitest::Test
    def test_a_byte_order_mark_is_dropped_as_ruby_drops_it
      root = my_app("device(Devices::IMU, as: 'imu')\n")
      imu = File.join(root, 'models', 'devices', 'imu.rb')
      File.binwrite(imu, "\xEF\xBB\xBF".b + File.binread(imu))
      conf = File.join(root, 'config', 'orogen', 'imu::Task.yml')
      FileUtils.mkdir_p(File.dirname(conf))
      File.binwrite(conf, "\xEF\xBB\xBF--- name:default\nrate: 50\n".b)
      out, err, status = run_cli('plan', '--app', root, '--format', 'json')
      assert_equal 0, status, err
      assert_match(/"rate": 50/, out)
    end

    def test_a_fifo_under_models_is_a_warning_and_is_never_read
      root = my_app(nil)
      File.mkfifo(File.join(root, 'models', 'devices', 'pipe.rb'))
      out, _, status = Timeout.timeout(20) { run_cli('check', '--app', root) }
      assert_equal 0, status, out
      assert_match(%r{^models/devices/pipe.rb:1: warning: pipe.rb is a named pipe, not a file: it is not loaded$},
                   out)
    end

    def test_a_symlink_loop_under_models_is_a_warning
      root = my_app(nil)
      File.symlink('loop.rb', File.join(root, 'models', 'devices', 'loop.rb'))
      out, = run_cli('check', '--app', root)
      assert_match(%r{^models/devices/loop.rb:1: warning: loop.rb is a broken symlink}, out)
    end

    def test_a_reader_that_goes_away_ends_the_command_quietly
      root = my_app("device(Devices::IMU, as: 'imu')\n")
      Open3.popen3(SelfTest.child_env, RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), 'plan', '--app', root,
                   '--format', 'json', unsetenv_others: true) do |_in, out, err, wait|
        out.close
        assert_equal 0, wait.value.exitstatus
        assert_empty err.read
      end
    end

    def test_ctrl_c_exits_quietly_with_status_one_hundred_thirty
      ready = File.join(Dir.mktmpdir('syskit-ready'), 'loading')
      (@tmpdirs ||= []) << File.dirname(ready)
      # A model file that says it is being loaded, then takes its time.
      root = my_app(nil, 'models/devices/slow.rb' => "File.write(#{ready.inspect}, '')\nsleep 30\n")
      Open3.popen3(SelfTest.child_env, RbConfig.ruby, File.join(GEM_ROOT, 'bin', 'syskit'), 'check', '--app', root,
                   unsetenv_others: true) do |_in, out, err, wait|
        deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 30
        sleep 0.02 until File.exist?(ready) || Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
        Process.kill('INT', wait.pid)
        assert_equal 130, wait.value.exitstatus
        assert_empty out.read
        assert_empty err.read
      end
    end
  end
end
