# frozen_string_literal: true

module Syskit
  module Bus
    # A progress bar on a terminal (stderr) while a large log is read.
    # Replays into a pipe or of small logs show none: it would only be noise.
    class Progress
      WIDTH = 30
      # Logs smaller than this are read too fast for a bar to be useful.
      MIN_BYTES = 8 << 20
      # Seconds between redraws, so that drawing never costs much.
      INTERVAL = 0.1

      # A bar on +out+ for reading +total+ bytes, or nil when +out+ is not a
      # terminal or the log is small.
      def self.for(total, out: $stderr, min_bytes: MIN_BYTES)
        new(total, out) if out&.tty? && total >= min_bytes
      end

      def initialize(total, out)
        @total = total.positive? ? total : 1
        @out = out
        @last = 0.0
      end

      # Shows that +bytes+ of the log have been read, +frames+ frames seen.
      def update(bytes, frames)
        now = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        return if now - @last < INTERVAL

        @last = now
        done = (bytes.to_f / @total).clamp(0.0, 1.0)
        filled = (done * WIDTH).round
        @out.print(format("\r[%<bar>s] %<pct>3d%% %<frames>d frames", bar: ('#' * filled).ljust(WIDTH),
                                                                      pct: (done * 100).floor, frames: frames))
      end

      # Erases the bar.
      def finish
        @out.print("\r\e[K")
      end
    end
  end
end
