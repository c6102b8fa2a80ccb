# frozen_string_literal: true

require 'fileutils'
require 'syskit/errors'

module Syskit
  module Generators
    # Writes the files of one generator run, all or nothing.
    #
    # Every file is checked before anything is written: it must land inside
    # one of the allowed directories once symlinks are resolved, and must not
    # exist unless +force+ is set. Then each file is written to a temporary
    # file in its own directory and the temporaries are renamed into place,
    # so that a failure half-way leaves no partial file behind.
    class FileWriter
      # One file to write: its path relative to the root, its content, and
      # whether it replaces an existing file.
      Entry = Struct.new(:path, :content, :overwrite, keyword_init: true)

      attr_reader :root

      # +root+: the app directory the paths are relative to; +allowed+: the
      # directories (relative to +root+) files may be written in.
      def initialize(root, allowed: ['.'], force: false, dry_run: false)
        @root = File.expand_path(root)
        @allowed = allowed.map { |dir| real_target(File.expand_path(dir, @root)) }
        @force = force
        @dry_run = dry_run
      end

      # Checks +files+ (relative path => content) and writes them unless
      # this is a dry run. Returns the entries, in the order given.
      def write(files)
        entries = plan(files)
        commit(entries) unless @dry_run
        entries
      end

      private

      def plan(files)
        entries = files.map do |path, content|
          full = File.expand_path(path, root)
          check_inside(path, full)
          check_target(path, full)
          Entry.new(path: path, content: content, overwrite: File.exist?(full))
        end
        existing = entries.select(&:overwrite)
        return entries if existing.empty? || @force

        raise GeneratorError.new(
          "#{existing.size == 1 ? 'this file exists' : 'these files exist'}, nothing was written: " \
          "#{existing.map(&:path).join(', ')}",
          hint: 'remove or rename them, or pass --force to overwrite them (--dry-run shows what would be written)'
        )
      end

      # Resolves the existing part of +path+ with realpath, so that a
      # symlinked directory pointing out of the app is seen for what it is.
      def real_target(path)
        existing = path
        rest = []
        until File.exist?(existing) || File.symlink?(existing)
          rest.unshift(File.basename(existing))
          existing = File.dirname(existing)
        end
        File.join(File.realpath(existing), *rest)
      rescue Errno::ENOENT, Errno::ELOOP
        # A dangling or looping symlink: nowhere we can vouch for.
        nil
      end

      def check_inside(path, full)
        real = real_target(File.dirname(full))
        return if real && @allowed.compact.any? { |dir| real == dir || real.start_with?("#{dir}/") }

        raise GeneratorError.new(
          "#{path} would be written outside of #{allowed_description} (#{real || full})",
          hint: 'check that none of its directories is a symlink out of the app, and give names relative to models/'
        )
      end

      def check_target(path, full)
        check_parent(path, full)
        if File.symlink?(full)
          raise GeneratorError.new("#{path} is a symlink, generators do not write through symlinks",
                                   hint: 'remove the symlink, or generate under another name')
        elsif File.directory?(full)
          raise GeneratorError.new("#{path} is a directory",
                                   hint: 'remove or rename it, or generate under another name')
        end
      end

      # The closest existing parent must be a directory, not a file a
      # directory of +path+ would have to replace.
      def check_parent(path, full)
        parent = File.dirname(full)
        parent = File.dirname(parent) until File.exist?(parent)
        return if File.directory?(parent)

        raise GeneratorError.new("#{path} cannot be written: #{parent.delete_prefix("#{root}/")} is a file",
                                 hint: 'remove or rename that file, or generate under another name')
      end

      def allowed_description
        real_root = real_target(root)
        dirs = @allowed.compact.map { |dir| dir == real_root ? 'the app' : "#{dir.delete_prefix("#{real_root}/")}/" }
        dirs.join(' and ')
      end

      def commit(entries)
        created_dirs = []
        temps = {}
        entries.each do |entry|
          full = File.expand_path(entry.path, root)
          make_dirs(File.dirname(full), created_dirs)
          temps[entry] = write_temp(full, entry.content)
        end
        temps.each { |entry, temp| File.rename(temp, File.expand_path(entry.path, root)) }
      rescue SystemCallError => e
        temps.each_value { |temp| FileUtils.rm_f(temp) }
        created_dirs.reverse_each { |dir| Dir.rmdir(dir) if Dir.empty?(dir) }
        raise GeneratorError.new("cannot write the generated files, nothing was written: #{e.message}",
                                 hint: 'check the permissions of the app directory')
      end

      # mkdir -p, recording in +created+ the directories it made (outermost
      # first), so that a failure can remove them again.
      def make_dirs(dir, created)
        missing = []
        until File.directory?(dir)
          missing.unshift(dir)
          dir = File.dirname(dir)
        end
        missing.each do |d|
          Dir.mkdir(d)
          created << d
        end
      end

      def write_temp(full, content)
        temp = File.join(File.dirname(full), ".#{File.basename(full)}.#{Process.pid}.tmp")
        File.open(temp, File::WRONLY | File::CREAT | File::EXCL, 0o644) { |io| io.write(content) }
        temp
      end
    end
  end
end
