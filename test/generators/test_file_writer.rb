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
        assert_match(/outside of models/, error.message)
        File.symlink(File.join(@outside, 'target.rb'), File.join(@root, 'models', 'devices', 'file_link.rb'))
        error = assert_raises(GeneratorError) { writer(force: true).write('models/devices/file_link.rb' => "x\n") }
        assert_match(/is a symlink/, error.message)
        assert_empty Dir.children(@outside)
      end

      def test_a_file_in_the_way_of_a_directory_is_refused
        error = assert_raises(GeneratorError) { writer.write('models/devices/existing.rb/x.rb' => "x\n") }
        assert_equal 'models/devices/existing.rb/x.rb cannot be written: models/devices/existing.rb is a file',
                     error.message
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
