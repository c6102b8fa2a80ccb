# frozen_string_literal: true

require 'helper'
require 'minitest/mock'
require 'syskit/generators/file_writer'

module Syskit
  module Generators
    # Generated files are written all or nothing, inside the app only.
    class TestFileWriter < Minitest::Test
      def setup
        @root = write_app({ 'models/devices/existing.rb' => "old\n" })
        @outside = Dir.mktmpdir('syskit-outside')
        (@tmpdirs ||= []) << @outside
      end

      def writer(**options)
        FileWriter.new(@root, allowed: %w[models test], **options)
      end

      # Every file under the app (temporary files included), relative to it.
      def app_files
        Dir.glob('**/*', File::FNM_DOTMATCH, base: @root).select { |f| File.file?(File.join(@root, f)) }.sort
      end

      def test_writes_files_and_their_directories
        entries = writer.write('models/devices/a/b.rb' => "b\n", 'test/devices/a/test_b.rb' => "t\n")
        assert_equal %w[models/devices/a/b.rb test/devices/a/test_b.rb], entries.map(&:path)
        assert_equal "b\n", File.read(File.join(@root, 'models/devices/a/b.rb'))
        assert_equal %w[models/devices/a/b.rb models/devices/existing.rb test/devices/a/test_b.rb], app_files
      end

      def test_an_existing_file_stops_everything
        error = assert_raises(GeneratorError) do
          writer.write('models/devices/new.rb' => "new\n", 'models/devices/existing.rb' => "new\n")
        end
        assert_equal 'this file exists, nothing was written: models/devices/existing.rb', error.message
        assert_match(/--force/, error.hint)
        assert_equal %w[models/devices/existing.rb], app_files
        assert_equal "old\n", File.read(File.join(@root, 'models/devices/existing.rb'))
      end

      def test_force_overwrites
        entries = writer(force: true).write('models/devices/existing.rb' => "new\n")
        assert entries.first.overwrite
        assert_equal "new\n", File.read(File.join(@root, 'models/devices/existing.rb'))
      end

      def test_a_dry_run_writes_nothing
        entries = writer(dry_run: true).write('models/devices/a/b.rb' => "b\n")
        assert_equal ['models/devices/a/b.rb'], entries.map(&:path)
        refute File.exist?(File.join(@root, 'models/devices/a'))
      end

      def test_files_outside_the_allowed_directories_are_refused
        ['config/x.rb', '../x.rb', 'models/../config/x.rb'].each do |path|
          error = assert_raises(GeneratorError, path) { writer.write(path => "x\n") }
          assert_match(%r{would be written outside of models/ and test/}, error.message)
        end
        assert_equal %w[models/devices/existing.rb], app_files
      end

      def test_symlinks_out_of_the_app_are_refused
        File.symlink(@outside, File.join(@root, 'models', 'devices', 'link'))
        error = assert_raises(GeneratorError) { writer.write('models/devices/link/x/y.rb' => "x\n") }
        assert_match(/symlink out of the app/, error.message)
        assert_equal 'models/devices/link', error.location.to_s(@root)
        File.symlink(File.join(@outside, 'target.rb'), File.join(@root, 'models', 'devices', 'file_link.rb'))
        error = assert_raises(GeneratorError) { writer(force: true).write('models/devices/file_link.rb' => "x\n") }
        assert_match(/is a symlink/, error.message)
        assert_empty Dir.children(@outside)
      end

      # models/ or test/ itself a symlink out of the app: the allowed
      # directory is not in the app, nothing may be written through it.
      def test_top_level_directories_that_are_symlinks_out_of_the_app_are_refused
        %w[models test].each do |top|
          FileUtils.rm_rf(File.join(@root, top))
          File.symlink(@outside, File.join(@root, top))
          error = assert_raises(GeneratorError) { writer.write("#{top}/devices/x.rb" => "x\n") }
          assert_equal "this directory is a symlink out of the app (to #{File.realpath(@outside)}): " \
                       "#{top}/devices/x.rb would be written there", error.message
          assert_equal top, error.location.to_s(@root)
          assert_empty Dir.children(@outside)
          File.unlink(File.join(@root, top))
          FileUtils.mkdir_p(File.join(@root, top))
        end
      end

      # A symlink to a directory inside the app is followed: it stays in.
      def test_symlinks_inside_the_app_are_followed
        FileUtils.mkdir_p(File.join(@root, 'models', 'real'))
        File.symlink(File.join(@root, 'models', 'real'), File.join(@root, 'models', 'devices', 'link'))
        writer.write('models/devices/link/x.rb' => "x\n")
        assert_equal "x\n", File.read(File.join(@root, 'models', 'real', 'x.rb'))
      end

      def test_a_file_in_the_way_of_a_directory_is_refused
        error = assert_raises(GeneratorError) { writer.write('models/devices/existing.rb/x.rb' => "x\n") }
        assert_equal 'models/devices/existing.rb/x.rb cannot be written: models/devices/existing.rb is a file',
                     error.message
      end

      # --force: the second rename fails after the first file was replaced;
      # the first gets its content back and the new file goes.
      def test_a_failure_after_a_file_was_replaced_restores_it
        FileUtils.mkdir_p(File.join(@root, 'test'))
        rename = File.method(:rename)
        renames = 0
        failing = lambda do |from, to|
          renames += 1
          raise Errno::ENOSPC, 'rename' if to.end_with?('test_b.rb')

          rename.call(from, to)
        end
        File.stub(:rename, failing) do
          error = assert_raises(GeneratorError) do
            writer(force: true).write('models/devices/existing.rb' => "new\n", 'models/devices/a/b.rb' => "b\n",
                                      'test/test_b.rb' => "t\n")
          end
          assert_match(/cannot write the generated files, nothing was written/, error.message)
        end
        assert_operator renames, :>=, 3
        assert_equal "old\n", File.read(File.join(@root, 'models/devices/existing.rb'))
        assert_equal %w[models/devices/existing.rb], app_files
        refute File.exist?(File.join(@root, 'models/devices/a'))
      end

      # The disk fills up while the second temporary file is written.
      def test_a_failed_write_leaves_no_temporary_file_nor_new_directory
        open = File.method(:open)
        failing = lambda do |path, *args, **kw, &block|
          return open.call(path, *args, **kw, &block) unless path.include?('test_b.rb')

          full_disk = Object.new
          def full_disk.write(*) = raise(Errno::ENOSPC, 'write')
          open.call(path, *args, **kw) { block.call(full_disk) }
        end
        File.stub(:open, failing) do
          error = assert_raises(GeneratorError) do
            writer.write('models/devices/a/b.rb' => "b\n", 'test/devices/test_b.rb' => "t\n")
          end
          assert_match(/nothing was written: No space left on device/, error.message)
        end
        assert_equal %w[models/devices/existing.rb], app_files
        refute File.exist?(File.join(@root, 'models/devices/a'))
        refute File.exist?(File.join(@root, 'test'))
      end

      # Ctrl-C half-way: undone too, and the interrupt goes on.
      def test_an_interrupt_is_undone_and_raised_again
        rename = File.method(:rename)
        File.stub(:rename, ->(from, to) { to.end_with?('test_b.rb') ? raise(Interrupt) : rename.call(from, to) }) do
          assert_raises(Interrupt) do
            writer(force: true).write('models/devices/existing.rb' => "new\n", 'test/test_b.rb' => "t\n")
          end
        end
        assert_equal "old\n", File.read(File.join(@root, 'models/devices/existing.rb'))
        assert_equal %w[models/devices/existing.rb], app_files
      end

      def test_a_failure_while_writing_removes_the_temporary_files_and_new_directories
        File.stub(:rename, ->(*) { raise Errno::EACCES, 'rename' }) do
          error = assert_raises(GeneratorError) do
            writer.write('models/devices/a/b.rb' => "b\n", 'test/devices/test_b.rb' => "t\n")
          end
          assert_match(/cannot write the generated files, nothing was written/, error.message)
        end
        assert_equal %w[models/devices/existing.rb], app_files
        refute File.exist?(File.join(@root, 'models/devices/a'))
        refute File.exist?(File.join(@root, 'test'))
      end
    end
  end
end
