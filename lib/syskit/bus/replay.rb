# frozen_string_literal: true

require 'syskit/bus/errors'
require 'syskit/bus/candump_log'
require 'syskit/printable'
require 'syskit/bus/traffic'
require 'syskit/bus/report'
require 'syskit/bus/progress'

module Syskit
  module Bus
    # `syskit bus replay`: reads a candump log and reports what each device
    # of a bus would have received.
    class Replay
      # Lines between two progress updates; a power of two keeps the check cheap.
      PROGRESS_EVERY = 1 << 14

      attr_reader :log

      # +dispatcher+: the bus (Dispatcher); +path+: the candump log;
      # +interface+: the log interface to read (default: the first seen);
      # +source+: what the report says about the plan (profile, robot).
      # +declared_bus+: the plan's entry of the bus, whose declared frames
      # the log is compared with (nil: no comparison).
      # +progress_out+ gets a progress bar when it is a terminal and the log
      # has at least +progress_min_bytes+.
      def initialize(dispatcher, path, interface: nil, source: {}, declared_bus: nil, progress_out: $stderr,
                     progress_min_bytes: Progress::MIN_BYTES)
        @dispatcher = dispatcher
        @declared_bus = declared_bus
        @path = path
        @log = CandumpLog.new(path, interface: interface)
        @source = source
        @progress_out = progress_out
        @progress_min_bytes = progress_min_bytes
      end

      # Reads the whole log; returns the Report. With +strict+, a malformed
      # line raises a LogError located at the first one.
      def run(strict: false)
        traffic = Traffic.new
        File.open(@path, 'rb') do |io|
          progress = Progress.for(io.size, out: @progress_out, min_bytes: @progress_min_bytes)
          begin
            log.read(io, traffic, every: PROGRESS_EVERY) { |frames| progress&.update(io.pos, frames) }
          ensure
            progress&.finish
          end
        end
        raise strict_error if strict && log.malformed_count.positive?
        raise order_error if strict && log.backwards

        Report.new(@dispatcher, traffic, source: source_info, declared_bus: @declared_bus)
      rescue SystemCallError, IOError => e
        raise LogError.new("cannot read #{@path}: #{e.message}", hint: 'give the path of a log written by candump -l')
      end

      private

      # Interface names and lines come from the log's bytes: made printable.
      def source_info
        others = log.other_interfaces.sort.to_h.transform_keys { |name| Printable.text(name) }
        interface = log.interface && Printable.text(log.interface)
        @source.merge(
          'log' => @path, 'interface' => interface, 'other_interfaces' => others, 'lines' => log.lines,
          'backwards' => backwards_hash(log.backwards),
          'malformed' => { 'count' => log.malformed_count, 'lines' => log.malformed.map { |m| malformed_hash(m) } }
        )
      end

      def malformed_hash(malformed)
        { 'line' => malformed.lineno, 'message' => Printable.text(malformed.message),
          'text' => Printable.text(malformed.text) }
      end

      # Times in seconds since the epoch, as the report's other times.
      def backwards_hash(backwards)
        backwards && { 'line' => backwards.lineno, 'time' => Report.seconds(backwards.time),
                       'previous_time' => Report.seconds(backwards.previous_time), 'lines' => backwards.lines }
      end

      def order_error
        first = log.backwards
        LogError.new(
          format('the log is not in time order: this line is %<seconds>.3f s before the line before it (%<lines>s ' \
                 'back in time)', seconds: (first.previous_time - first.time) / 1e6,
                                  lines: Naming.count(first.lines, 'line')),
          location: Location.new(@path, first.lineno),
          hint: 'gaps and periods are measured between lines in log order: sort the log by time, or replay the ' \
                'logs merged into it one by one'
        )
      end

      def strict_error
        first = log.malformed.first
        more = log.malformed_count - 1
        others = ''
        others = " (and #{more} more malformed #{more == 1 ? 'line' : 'lines'})" if more.positive?
        LogError.new("malformed candump line: #{first.message}#{others}",
                     location: Location.new(@path, first.lineno),
                     hint: 'lines look like "(1436509053.249713) can0 123#DEADBEEF" (candump -l); ' \
                           'without --strict, malformed lines are skipped and reported')
      end
    end
  end
end
