# frozen_string_literal: true

require 'helper'

module Syskit
  # bin/syskit keeps the gem's compiled code between runs (ISeqCache): a
  # run from the cache prints what a run without it prints, and an entry
  # that does not match its source is compiled again, never used.
  class TestISeqCache < Minitest::Test
    parallelize_me!

    EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')

    def plan(env)
      out, err, status = syskit_process('plan', '--app', EXAMPLE, env: env)
      assert status.success?, err
      out
    end

    def test_runs_from_the_cache_print_what_runs_without_it_print
      Dir.mktmpdir do |dir|
        expected = plan('SYSKIT_NO_CACHE' => '1')
        assert_empty Dir.children(dir)
        assert_equal expected, plan('SYSKIT_CACHE_DIR' => dir)
        entries = Dir[File.join(dir, '*', '*.iseq')].map { |f| File.basename(f) }
        assert(entries.any? { |e| e.end_with?('-lib-syskit-network-generator.rb.iseq') }, entries.inspect)
        # The installed libraries it loads are kept too (Psych, from Ruby's
        # own directory), the app's small files are not.
        psych = "#{File.join(RbConfig::CONFIG['rubylibdir'], 'psych.rb').tr('/', '-')}.iseq"
        assert_includes entries, psych
        refute(entries.any? { |e| e.include?('awesome_robot') }, entries.inspect)
        assert_equal expected, plan('SYSKIT_CACHE_DIR' => dir)
      end
    end

    def test_an_entry_that_does_not_match_its_source_is_compiled_again
      Dir.mktmpdir do |dir|
        expected = plan('SYSKIT_CACHE_DIR' => dir)
        entries = Dir[File.join(dir, '*', '*.iseq')]
        # Each entry takes the next one's content (another file's code,
        # under another key), and one is cut short.
        contents = entries.map { |e| File.binread(e) }
        entries.zip(contents.rotate).each { |entry, content| File.binwrite(entry, content) }
        File.binwrite(entries.first, contents.first.byteslice(0, 40))
        assert_equal expected, plan('SYSKIT_CACHE_DIR' => dir)
        # Each entry is its own file's again: its key (the header line
        # naming the file, its size and time) is back. The compiled code
        # after it need not be the same bytes as the first compilation's.
        key = ->(data) { data.b[/\A[^\n]*\n/] }
        assert_equal(contents.map(&key), entries.map { |e| key.call(File.binread(e)) })
      end
    end

    # A large model file of the app is kept compiled too; edited, even to
    # the same size and modification time, it is compiled again.
    def test_a_large_model_file_is_kept_and_compiled_again_once_edited
      Dir.mktmpdir do |dir|
        app = File.join(dir, 'awesome_robot')
        FileUtils.cp_r(EXAMPLE, app)
        profile = File.join(app, 'models', 'profiles', 'live', 'base.rb')
        # Padded past ISeqCache::APP_MIN_BYTES with comment lines.
        File.write(profile, File.read(profile) + ("# padding\n" * 8000))
        cache = File.join(dir, 'cache')
        assert_includes plan_of(app, cache), 'devices     forward_camera'
        assert(Dir[File.join(cache, '*', '*.iseq')].any? { |e| e.end_with?('-live-base.rb.iseq') })

        stat = File.stat(profile)
        File.write(profile, File.read(profile).gsub('forward_camera', 'fronts_camera1'))
        File.utime(stat.atime, stat.mtime, profile)
        assert_equal stat.size, File.size(profile)
        edited = plan_of(app, cache)
        assert_includes edited, 'fronts_camera1'
        refute_includes edited, 'devices     forward_camera'
      end
    end

    # A large robot file too (the 10,000-device robot of rake bench has
    # 0.7 MB of use_deployment statements).
    def test_a_large_robot_file_is_kept
      Dir.mktmpdir do |dir|
        app = File.join(dir, 'awesome_robot')
        FileUtils.cp_r(EXAMPLE, app)
        robot = File.join(app, 'config', 'robots', 'default.rb')
        File.write(robot, File.read(robot) + ("# padding\n" * 8000))
        cache = File.join(dir, 'cache')
        expected = plan('SYSKIT_NO_CACHE' => '1')
        assert_equal expected, plan_of(app, cache)
        assert(Dir[File.join(cache, '*', '*.iseq')].any? { |e| e.end_with?('-robots-default.rb.iseq') })
        assert_equal expected, plan_of(app, cache)
      end
    end

    # The key of an app file holds its path and its text: a path that is not
    # UTF-8 and a text that is not ASCII still make one.
    def test_an_app_file_whose_path_and_text_do_not_mix_is_kept
      Dir.mktmpdir do |dir|
        script = <<~'RUBY'
          require 'syskit/iseq_cache'
          Syskit::ISeqCache.install
          source = "# caf\u00e9\n" + ("x = 1\n" * 20_000) + "x + 1\n"
          path = File.join(ARGV[0], "caf\xE9.rb".b)
          2.times { puts Syskit::ISeqCache.compile(source, path).eval }
        RUBY
        out, err, status = ruby_process('-e', script, dir, chdir: dir,
                                                           env: { 'SYSKIT_CACHE_DIR' => File.join(dir, 'cache') })
        assert status.success?, err
        assert_equal "2\n2\n", out
        assert_equal 1, Dir[File.join(dir, 'cache', '*', '*.iseq')].size
      end
    end

    def plan_of(app, cache)
      out, err, status = syskit_process('plan', '--app', app, env: { 'SYSKIT_CACHE_DIR' => cache })
      assert status.success?, err
      out
    end
  end
end
