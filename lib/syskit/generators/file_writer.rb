# frozen_string_literal: true

require 'fileutils'
require 'syskit/errors'
require 'syskit/generators/file_transaction'

module Syskit
  module Generators
    # Writes the files of one generator run, all or nothing.
    #
    # Every file is checked before anything is written: it must land inside
    # one of the allowed directories once symlinks are resolved, and must not
    # exist unless +force+ is set. Then each file is written to a temporary
    # file in its own directory and the temporaries are renamed into place
    # (see FileTransaction): a failure half-way is undone.
    class FileWriter
      # One file to write: its path relative to the root, its content, and
      # whether it replaces an existing file.
      Entry = Struct.new(:path, :content, :overwrite, keyword_init: true)

      attr_reader :root

      # +root+: the app directory the paths are relative to; +allowed+: the
      # directories (relative to +root+) files may be written in.
      def initialize(root, allowed: ['.'], force: false, dry_run: false)
        @root = File.expand_path(root)
        @real_root = real_target(@root)
        # An allowed directory that is a symlink out of the app (models ->
        # /elsewhere) allows nothing: files are written in the app only.
        @allowed = allowed.map { |dir| real_target(File.expand_path(dir, @root)) }
                          .select { |dir| dir && @real_root && within?(dir, @real_root) }
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
        return if real && @allowed.any? { |dir| within?(real, dir) }

        link, target = escaping_symlink(path)
        if link
          raise GeneratorError.new(
            "this directory is a symlink out of the app (to #{target}): #{path} would be written there",
            location: Location.new(File.join(root, link), nil),
            hint: 'generators write in the app only: make it a directory of the app, or generate in the app it links to'
          )
        end

        raise GeneratorError.new(
          "#{path} would be written outside of #{allowed_description} (#{real || full})",
          hint: 'check that none of its directories is a symlink out of the app, and give names relative to models/'
        )
      end

      def within?(path, dir)
        path == dir || path.start_with?("#{dir}/")
      end

      # The first directory of +path+ (relative to the root) that is a
      # symlink pointing out of the app, and where it points.
      def escaping_symlink(path)
        parts = File.dirname(path).split('/')
        parts.each_index do |i|
          link = parts[0..i].join('/')
          full = File.join(root, link)
          next unless File.symlink?(full)

          target = real_target(full)
          return [link, target || File.readlink(full)] unless target && @real_root && within?(target, @real_root)
        end
        nil
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
        dirs = @allowed.map { |dir| dir == real_root ? 'the app' : "#{dir.delete_prefix("#{real_root}/")}/" }
        dirs.join(' and ')
      end

      # Writes every file to a temporary file, then renames them all into
      # place; on any failure (or Ctrl-C) what was done is undone.
      def commit(entries)
        transaction = FileTransaction.new
        temps = entries.map do |entry|
          full = File.expand_path(entry.path, root)
          transaction.make_dirs(File.dirname(full))
          [transaction.write_temp(full, entry.content), full]
        end
        temps.each { |temp, full| transaction.place(temp, full) }
        transaction.finish
      rescue Exception => e # rubocop:disable Lint/RescueException -- undo, then report or re-raise
        left = transaction.roll_back
        raise unless e.is_a?(SystemCallError) || e.is_a?(IOError)

        raise write_error(e, left)
      end

      def write_error(error, left)
        if left.empty?
          return GeneratorError.new("cannot write the generated files, nothing was written: #{error.message}",
                                    hint: 'check the permissions of the app directory and the space left on its disk')
        end

        GeneratorError.new(
          "cannot write the generated files (#{error.message}), and could not undo everything: #{left.join('; ')}",
          hint: 'restore these files by hand (from their backup, or version control)'
        )
      end
    end
  end
end
