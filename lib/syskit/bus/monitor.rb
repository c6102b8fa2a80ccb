# frozen_string_literal: true

require 'io/wait'
require 'syskit/bus/frame_reader'
require 'syskit/bus/socketcan'
require 'syskit/bus/traffic'
require 'syskit/bus/report'
require 'syskit/bus/report_text'

module Syskit
  module Bus
    # `syskit bus monitor`: counts the frames read from a live bus and shows
    # the replay table, refreshed every +interval+ seconds, until Ctrl-C, the
    # end of the input or +duration+ seconds.
    class Monitor
      CLEAR = "\e[H\e[2J"
      # Frames read between two looks at the clock on a busy bus.
      CLOCK_EVERY = 256

      # +io+: where frames come from (a raw CAN socket from SocketCAN.open,
      # or any IO FrameReader can read); +live+: draw the table at each
      # refresh on +out+ (clearing the screen when +out+ is a terminal);
      # +declared_bus+: the plan's entry of the bus, whose declared frames
      # the report compares with what is read, as replay does.
      def initialize(dispatcher, io, source: {}, out: $stdout, interval: 1.0, live: true, reader: nil,
                     declared_bus: nil)
        @dispatcher = dispatcher
        @declared_bus = declared_bus
        @reader = reader || FrameReader.new(io)
        @io = io
        @source = source
        @out = out
        @interval = interval.to_f
        @live = live
        @traffic = Traffic.new
      end

      # Reads until stopped; returns the final Report.
      def run(duration: nil)
        start = now
        deadline = duration && (start + duration)
        @next_refresh = start + @interval
        # Rates of the first interval count from the start of monitoring.
        @previous = [start, {}]
        loop do
          break unless read_until([@next_refresh, deadline].compact.min)

          refresh if now >= @next_refresh
          break if deadline && now >= deadline
        end
        finish
      rescue Interrupt
        # Ctrl-C is how a monitor is meant to stop: finish with the totals.
        finish
      end

      # The report of what has been read so far.
      def report
        Report.new(@dispatcher, @traffic, source: @source, declared_bus: @declared_bus)
      end

      private

      # The final report; the live table is wiped from a terminal first, as
      # the report replaces it.
      def finish
        @out.write(CLEAR) if @live && @out.tty?
        report
      end

      # Reads every frame available until +time+ (monotonic seconds); false
      # at the end of the input.
      def read_until(time)
        loop do
          frame = @reader.read_nonblock
          return false if frame.nil?

          if frame == :wait_readable
            left = time - now
            return true if left <= 0

            @io.wait_readable(left)
          else
            @traffic.add(frame)
            # A busy bus never leaves the socket empty: look at the clock
            # now and then, or the table would never be refreshed.
            return true if (@traffic.frames % CLOCK_EVERY).zero? && now >= time
          end
        end
      end

      def refresh
        at = now
        current = report
        recent = recent_rates(current, at)
        @previous = [at, current.devices.to_h { |d| [d.name, d.frames] }]
        @next_refresh += @interval while @next_refresh <= at
        return unless @live

        @out.write(CLEAR) if @out.tty?
        @out.write("#{ReportText.render(current, recent: recent)}\n(Ctrl-C to stop)\n\n")
        @out.flush
      end

      # Frames per second of each device since the previous refresh.
      def recent_rates(report, at)
        since, counts = @previous
        elapsed = at - since
        report.devices.to_h { |d| [d.name, elapsed.positive? ? (d.frames - counts.fetch(d.name, 0)) / elapsed : nil] }
      end

      def now
        Process.clock_gettime(Process::CLOCK_MONOTONIC)
      end
    end
  end
end
