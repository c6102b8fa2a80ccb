# frozen_string_literal: true

module Syskit
  # A place in a user's file: where a declaration was made or an error comes from.
  Location = Struct.new(:path, :lineno)

  # Finding the user's frame in a call stack, and printing it as file:line.
  class Location
    # The gem's own code; frames in here are never "the user's line".
    GEM_LIB = File.expand_path('..', __dir__)
    SEPARATOR = '/'.ord

    # The first frame of the current call stack that is outside the gem's
    # library code, i.e. the user's DSL call that led here.
    def self.of_caller
      # Only the gem's methods call this: frame 1, their own, is never the
      # user's. The user's frame is usually the next one, the DSL method's
      # caller: it is asked for alone (one frame object, where a 10,000-
      # device robot makes ~40,000 of these calls while loading), then the
      # stack further up a batch at a time, never materialized whole.
      # (A while loop: +return+ from inside a block, as +batch.each { ... }+
      # would need, costs an object on every call.)
      start = 2
      length = 1
      while (batch = caller_locations(start, length)) && !batch.empty?
        i = 0
        while i < batch.size
          return from(batch[i]) if user_frame?(batch[i])

          i += 1
        end
        start += batch.size
        length = 8
      end
      nil
    end

    # The first frame of an exception's backtrace that is outside the gem.
    def self.of_exception(exception)
      from((exception.backtrace_locations || []).find { |loc| user_frame?(loc) })
    end

    # The first frame of an exception's backtrace that is in +path+.
    def self.in_file(exception, path)
      from((exception.backtrace_locations || []).find { |loc| (loc.absolute_path || loc.path) == path })
    end

    def self.user_frame?(loc)
      path = loc.absolute_path || loc.path
      !path.start_with?(GEM_LIB, '<internal:')
    end

    # Paths are deduplicated: thousands of declarations share a few files.
    # A chain of DSL calls on one line (+device(...).can_id(...).period(...)+)
    # shares one Location: the last one made is given again for the same
    # line (Locations are frozen values).
    def self.from(loc)
      return unless loc

      path = loc.absolute_path || loc.path
      lineno = loc.lineno
      last = @last
      return last if last && last.lineno == lineno && last.path == path

      @last = new(-path, lineno).freeze
    end

    # The path relative to +root+ (by default the loaded app's) when it is
    # inside it.
    def relative_path(root = Syskit.app&.root)
      return path unless root

      root = File.expand_path(root) unless root.start_with?('/')
      inside = path.start_with?(root) && path.getbyte(root.size) == SEPARATOR
      inside ? path[(root.size + 1)..] : path
    end

    # The text of the line, for messages that quote what was written
    # (read only when an error is reported; from the editor's buffer when
    # `syskit lsp` checks one, see UserFile.with_buffers); nil when it
    # cannot be read.
    def source_line
      return unless lineno&.positive?

      buffer = UserFile.buffer(path) if defined?(UserFile)
      return buffer.force_encoding(Encoding::UTF_8).lines[lineno - 1] if buffer

      File.foreach(path).with_index(1) { |line, i| return line if i == lineno }
      nil
    rescue SystemCallError, IOError, ArgumentError
      nil
    end

    # "file:line"; only the path for a location without a line (a
    # directory, a file as a whole).
    def to_s(root = Syskit.app&.root)
      lineno&.positive? ? "#{relative_path(root)}:#{lineno}" : relative_path(root)
    end
  end
end
