# frozen_string_literal: true

require 'rbconfig'

module Syskit
  # Compiled code of the gem's own files, kept between runs: compiling
  # lib/ takes most of a command's start-up (about 80 of 150 ms for
  # `syskit plan`), loading the compiled form a fifth of that. Ruby asks
  # RubyVM::InstructionSequence.load_iseq for each file it loads; for the
  # gem's files, and those of the installed libraries it loads (Thor,
  # Psych...: Ruby's, site and vendor directories and the gem
  # directories), this answers from the cache; other files, the user's,
  # are left to Ruby.
  #
  # The cache is a directory of one file per source file, named by its path
  # (SYSKIT_CACHE_DIR, else $XDG_CACHE_HOME/syskit, else ~/.cache/syskit),
  # each keyed by the source's path, size and modification time and by the
  # Ruby that compiled it: a changed file, or another Ruby, compiles again.
  # SYSKIT_NO_CACHE=1, a directory that cannot be written or an entry that
  # cannot be read only make loading as slow as without it.
  #
  # The app's large model files are kept too (#compile: the profile of a
  # 10,000-device robot is 1.5 MB of Ruby, 0.07 s to compile, 0.007 s to
  # load compiled); their entries hold the source text they were compiled
  # from, compared whole, so an edited file is always compiled again.
  # Files under APP_MIN_BYTES compile in less than a millisecond: they are
  # not kept, so apps made and thrown away (tests, generators) leave
  # nothing behind.
  module ISeqCache
    LIB = File.expand_path('..', __dir__)
    APP_MIN_BYTES = 64 * 1024

    class << self
      attr_reader :dir

      # Starts answering for the gem's files (once per process).
      def install
        return if @installed || ENV['SYSKIT_NO_CACHE'] || !defined?(RubyVM::InstructionSequence.load_from_binary)

        @dir = cache_dir
        return unless @dir

        @installed = true
        @libraries = library_dirs
        RubyVM::InstructionSequence.singleton_class.prepend(Hook)
      end

      # The compiled code of +path+, from the cache when it is current;
      # nil for files that are neither the gem's nor an installed
      # library's (Ruby compiles them).
      def fetch(path)
        return unless path.start_with?(*@libraries)

        entry = entry_of(path)
        key = key_of(path)
        cached = read(entry, key)
        return cached if cached

        iseq = RubyVM::InstructionSequence.compile_file(path)
        write(entry, key, iseq)
        iseq
      end

      # The compiled code of +source+ (a user's file at +path+, as it is to
      # be evaluated): from the cache when it holds this very text, else
      # compiled and kept. Without the cache (not installed: the gem used
      # as a library, the tests), or for a small file, compiled each time.
      def compile(source, path)
        unless @installed && source.bytesize >= APP_MIN_BYTES
          return RubyVM::InstructionSequence.compile(source, path, path, 1)
        end

        entry = entry_of(path)
        # As bytes: the path and the text may be in encodings that do not mix.
        key = "#{RUBY_DESCRIPTION}\0".b << path.b << "\0#{source.bytesize}\n" << source.b
        cached = read(entry, key)
        return cached if cached

        iseq = RubyVM::InstructionSequence.compile(source, path, path, 1)
        write(entry, key, iseq)
        iseq
      end

      private

      # Where installed Ruby libraries are: their files change only when
      # they are installed again, which changes their size or time.
      def library_dirs
        config = RbConfig::CONFIG
        dirs = [LIB, config['rubylibdir'], config['sitedir'], config['vendordir']]
        dirs.concat(Gem.path.map { |dir| File.join(dir, 'gems') }) if defined?(Gem)
        dirs.compact.map { |dir| File.join(dir, '') }.uniq
      end

      def cache_dir
        base = ENV.fetch('SYSKIT_CACHE_DIR') { user_cache_dir }
        return unless base

        dir = File.join(base, "iseq-#{RUBY_VERSION}-#{RUBY_PLATFORM}")
        make_directory(dir)
        File.writable?(dir) ? dir : nil
      rescue SystemCallError
        nil
      end

      # $XDG_CACHE_HOME/syskit, else ~/.cache/syskit; nil without a home.
      def user_cache_dir
        xdg = ENV.fetch('XDG_CACHE_HOME', nil)
        return File.join(xdg, 'syskit') if xdg && !xdg.empty?

        File.join(Dir.home, '.cache', 'syskit')
      rescue ArgumentError
        nil
      end

      # mkdir -p, without loading FileUtils (start-up is what this saves).
      def make_directory(dir)
        return if File.directory?(dir)

        make_directory(File.dirname(dir))
        Dir.mkdir(dir)
      rescue Errno::EEXIST
        nil
      end

      # One entry per source file, named by its whole path: two copies of
      # the gem (two versions installed, two checkouts) do not take each
      # other's entries.
      def entry_of(path)
        File.join(@dir, "#{path.tr('/', '-')}.iseq")
      end

      # What a cache entry must match: the source as it is now, and the
      # Ruby that loads it.
      def key_of(path)
        stat = File.stat(path)
        "#{RUBY_DESCRIPTION}\0#{path}\0#{stat.size}\0#{stat.mtime.to_r}\n"
      end

      def read(entry, key)
        data = File.binread(entry)
        return unless data.start_with?(key.b)

        RubyVM::InstructionSequence.load_from_binary(data.byteslice(key.bytesize..))
      rescue SystemCallError, RuntimeError, TypeError, ArgumentError
        nil
      end

      # Written to a temporary file then renamed, so that a process reading
      # it never sees half of it.
      def write(entry, key, iseq)
        temporary = "#{entry}.#{Process.pid}.tmp"
        File.binwrite(temporary, key.b + iseq.to_binary)
        File.rename(temporary, entry)
      rescue SystemCallError, RuntimeError
        File.unlink(temporary) if temporary && File.exist?(temporary)
      end
    end

    # Ruby's hook: called with the path of each file it loads; nil lets
    # Ruby compile it itself.
    module Hook
      def load_iseq(path)
        ISeqCache.fetch(path)
      end
    end
  end
end
