# frozen_string_literal: true

require 'syskit/can/timing/format'

module Syskit
  module CAN
    module Timing
      # A BusResult as a table for a terminal (`syskit bus timing`): one row
      # per frame in priority order, times in ms to the microsecond.
      module Table
        HEADER = %w[ID Device Bytes Period Deadline Jitter C Blocking Response Slack].freeze
        # Columns aligned left; the others are numbers.
        LEFT = %w[ID Device].freeze

        module_function

        # The table, under +title+ (e.g. "Bus can0 of Profile").
        def render(result, title)
          rows = result.frames.map { |r| row(r) }
          "#{title}: #{Format.bitrate(result.bitrate)}, utilisation #{Format.percent(result.utilization)}\n" \
            "worst-case response times (Davis et al. 2007); times in ms, C is the transmission time\n\n" \
            "#{table(rows)}\n#{summary(result)}\n"
        end

        # The cells of one frame's row.
        def row(result)
          f = result.frame
          [f.hex_id, f.device.to_s, f.bytes.to_s, ms(f.period), ms(f.deadline), ms(f.jitter),
           ms(result.transmission_time), ms(result.blocking), bound('>=', result, result.response_time),
           bound('<=', result, result.slack), status(result)]
        end

        # A time of a frame whose analysis stopped at its first late
        # instance is a bound: marked with +mark+.
        def bound(mark, result, seconds)
          result.stopped_at_miss ? "#{mark}#{ms(seconds)}" : ms(seconds)
        end

        # 'ok', 'MISS', or 'MISS (unbounded)'.
        def status(result)
          return 'ok' if result.schedulable?

          result.response_time ? 'MISS' : 'MISS (unbounded)'
        end

        # The verdict under the table.
        def summary(result)
          frames = Naming.count(result.frames.size, 'frame')
          misses = result.misses.size
          verdict = if misses.zero? then "every frame meets its deadline (#{frames})"
                    else "#{misses} of #{frames} can miss #{misses == 1 ? 'its' : 'their'} deadline"
                    end
          if result.frames.any?(&:stopped_at_miss)
            verdict += "\n>= a response time past the deadline is that of the frame's first late instance: " \
                       'the analysis stops there, later ones may take longer'
          end
          return verdict unless result.overloaded?

          "the bus is loaded #{Format.percent(result.utilization)}: it cannot carry this traffic\n#{verdict}"
        end

        # Milliseconds to the microsecond, '-' for nil.
        def ms(seconds)
          seconds ? format('%.3f', (seconds * 1000).to_f) : '-'
        end

        # Aligned columns; the status column, last, has no header.
        def table(rows)
          widths = HEADER.each_index.map { |i| ([HEADER[i]] + rows.map { |r| r[i] }).map(&:size).max }
          [HEADER, *rows].map do |cells|
            line = cells.each_with_index.map do |cell, i|
              next cell if i >= HEADER.size

              LEFT.include?(HEADER[i]) ? cell.ljust(widths[i]) : cell.rjust(widths[i])
            end
            "#{line.join('  ').rstrip}\n"
          end.join
        end
      end
    end
  end
end
