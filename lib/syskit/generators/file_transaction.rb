# frozen_string_literal: true

require 'fileutils'

module Syskit
  module Generators
    # Puts the files of one generator run in place, all of them or none.
    #
    # Everything it does is recorded as it is done (each directory made,
    # each temporary file, each file it replaced, kept under a backup name)
    # so that a failure at any step, or Ctrl-C, can be undone: new files and
    # directories removed, replaced files given back their content. Only
    # {#finish} removes the backups.
    class FileTransaction
      def initialize
        @created_dirs = []
        @temps = []
        @backups = []
        @placed = []
      end

      # mkdir -p +dir+, recording the directories made (outermost first).
      def make_dirs(dir)
        missing = []
        until File.directory?(dir)
          missing.unshift(dir)
          dir = File.dirname(dir)
        end
        missing.each do |d|
          Dir.mkdir(d)
          @created_dirs << d
        end
      end

      # Writes +content+ to a new temporary file next to +full+; returns its path.
      def write_temp(full, content)
        temp = hidden(full, 'tmp')
        File.open(temp, File::WRONLY | File::CREAT | File::EXCL, 0o644) do |io|
          # Recorded once created: a file of that name that was there
          # before (EEXIST) is not ours to remove.
          @temps << temp
          io.write(content)
        end
        temp
      end

      # Renames +temp+ to +full+; a file already at +full+ is kept under a
      # backup name until {#finish}.
      def place(temp, full)
        if File.exist?(full)
          backup = hidden(full, 'bak')
          File.rename(full, backup)
          @backups << [full, backup]
        end
        File.rename(temp, full)
        @temps.delete(temp)
        @placed << full
      end

      # Drops the backups: the run is done.
      def finish
        FileUtils.rm_f(@backups.map(&:last))
        @backups.clear
      end

      # Undoes what was done, newest first. Returns what could not be
      # undone, as messages (empty when the app is as it was).
      def roll_back
        left = []
        restored = @backups.to_h
        @placed.reverse_each { |full| attempt(left, "remove #{full}") { File.unlink(full) } unless restored.key?(full) }
        @backups.reverse_each do |full, backup|
          attempt(left, "restore #{full} (its previous content is in #{backup})") { File.rename(backup, full) }
        end
        @temps.each { |temp| attempt(left, "remove #{temp}") { File.unlink(temp) } }
        @created_dirs.reverse_each { |dir| attempt(left, "remove #{dir}") { Dir.rmdir(dir) if Dir.empty?(dir) } }
        left
      end

      private

      def attempt(left, what)
        yield
      rescue SystemCallError => e
        left << "#{what}: #{e.message}" unless e.is_a?(Errno::ENOENT)
      end

      # .NAME.PID.EXT in the directory of +full+: hidden, and not one of
      # the names a generator writes.
      def hidden(full, ext)
        File.join(File.dirname(full), ".#{File.basename(full)}.#{Process.pid}.#{ext}")
      end
    end
  end
end
