# frozen_string_literal: true

require 'syskit/bus/report'
require 'syskit/can/timing/format'

module Syskit
  module Bus
    # Renders a Report for a terminal: a table per device, then the ids no
    # device receives, the ids several devices receive and the malformed
    # lines. Times are seconds after the first frame seen.
    module ReportText
      STATUS_NOTES = {
        write_only: 'write-only (bus_to_client: false): receives nothing',
        no_filter: 'no can_id filter: receives nothing by filter'
      }.freeze
      DEVICE_HEADER = ['Device', 'Filter', 'Frames', 'IDs', 'First (s)', 'Last (s)', 'Rate (/s)'].freeze
      ID_HEADER = ['ID', 'Frames', 'First (s)', 'Last (s)'].freeze
      DECLARED_HEADER = ['ID', 'Device', 'Period (ms)', 'Frames', 'Mean (ms)', 'Worst (ms)', 'Note'].freeze
      # Columns aligned right (numbers), by header.
      RIGHT = ['Frames', 'IDs', 'First (s)', 'Last (s)', 'Rate (/s)', 'Now (/s)', 'Period (ms)', 'Mean (ms)',
               'Worst (ms)'].freeze

      module_function

      # The report as text; +recent+ (device name => frames/s) adds the
      # monitor's "last interval" column.
      def render(report, recent: nil)
        [header(report), devices(report, recent), unclaimed(report), overlaps(report), declared(report),
         malformed(report)].compact.join("\n")
      end

      def header(report)
        lines = [title(report), totals(report), kinds(report.traffic), skipped(report.source), order(report)]
        "#{lines.compact.join("\n")}\n"
      end

      # Where a log goes back in time: its gaps and periods are between
      # lines in log order, not in time order.
      def order(report)
        back = report.source['backwards']
        return unless back

        seconds = back['previous_time'] - back['time']
        format('  not in time order: line %<line>d is %<seconds>.3f s before the line before it (%<lines>s back ' \
               'in time): gaps, periods and late frames are measured in log order, sort the log by time',
               line: back['line'], seconds: seconds, lines: Naming.count(back['lines'], 'line'))
      end

      def title(report)
        src = report.source
        text = "Bus #{report.bus}"
        text += " of #{src['profile']}" if src['profile']
        text += " (robot #{src['robot']})" if src['robot']
        text
      end

      def totals(report)
        src = report.source
        from = [src['log'] && "log #{src['log']}", src['interface'] && "interface #{src['interface']}"]
        span = report.duration ? format(' in %.3f s', report.duration) : ''
        "#{from.compact.join(', ')}: #{Naming.count(report.traffic.frames, 'frame')}#{span}"
      end

      def kinds(traffic)
        "  standard #{traffic.standard}, extended #{traffic.extended}, CAN FD #{traffic.fd}, RTR #{traffic.rtr}, " \
          "error frames #{traffic.errors}"
      end

      def skipped(source)
        others = source['other_interfaces']
        return unless others&.any?

        "  skipped frames of other interfaces: #{others.map { |i, n| "#{i} (#{n})" }.join(', ')} " \
          '(choose one with --interface)'
      end

      def devices(report, recent)
        head = recent ? DEVICE_HEADER + ['Now (/s)'] : DEVICE_HEADER
        rows = report.devices.map do |d|
          note = STATUS_NOTES[d.status]
          next [d.name, note] if note

          row = [d.name, filter(d.can_filter), d.frames.to_s, d.keys.size.to_s,
                 time(report, d.first_time), time(report, d.last_time), number(d.rate)]
          recent ? row + [number(recent[d.name])] : row
        end
        table(head, rows)
      end

      def unclaimed(report)
        rows = report.unclaimed
        title = "Frames no device receives: #{count(rows)}"
        return "#{title}\n" if rows.empty?

        head = ID_HEADER
        body = rows.map { |r| id_cells(report, r) }
        notes = rows.map { |r| unclaimed_note(r) }
        if notes.any?
          head += ['Note']
          body = body.zip(notes).map { |cells, note| cells + [note.to_s] }
        end
        "#{title}\n#{table(head, body, indent: '  ')}"
      end

      # Who is behind a frame no device receives: the devices declaring it
      # (.frame), which the host sends it to, else the write-only devices
      # whose filter it matches.
      def unclaimed_note(row)
        if row.declared_by.any? then "declared by #{row.declared_by.join(', ')}: host to device"
        elsif row.writers.any? then "filter of write-only #{row.writers.join(', ')}"
        end
      end

      def overlaps(report)
        rows = report.overlaps
        title = "Frames several devices receive: #{count(rows)}"
        return "#{title}\n" if rows.empty?

        body = rows.map { |r| id_cells(report, r) + [r.devices.join(', ')] }
        "#{title}\n#{table(ID_HEADER + ['Devices'], body, indent: '  ')}"
      end

      # The log against the traffic the plan declares on the bus.
      def declared(report)
        declared = report.declared
        return unless declared

        [declared_frames(declared), undeclared(declared), bus_load(declared)].join("\n")
      end

      def declared_frames(declared)
        rows = declared.rows
        title = "Declared frames: #{rows.size}, #{rows.size - declared.unseen.size} seen\n"
        return title if rows.empty?

        body = rows.map do |r|
          f = r.frame
          [Frame.key_to_s(Frame.key(f.id, f.extended)), f.device, ms(f.period), r.frames.to_s, ms(r.mean_period),
           ms(r.worst_period), declared_note(r)]
        end
        "#{title}#{table(DECLARED_HEADER, body, indent: '  ')}"
      end

      def declared_note(row)
        return 'never seen' if row.frames.zero?

        notes = []
        notes << 'late: longer than period + jitter' if row.late?
        notes << "silent for the last #{ms(row.silent_for).strip} ms of the log" if row.silent_at_end?
        notes.join('; ')
      end

      def undeclared(declared)
        rows = declared.undeclared
        title = "Frames seen but never declared: #{count(rows)}\n"
        return title if rows.empty?

        "#{title}#{table(%w[ID Frames], rows.map { |u| [Frame.key_to_s(u.key), u.frames.to_s] }, indent: '  ')}"
      end

      def bus_load(declared)
        bus = declared.bus
        return "No bitrate declared: no bus load\n" unless bus.bitrate

        rate = CAN::Timing::Format.bitrate(bus.bitrate)
        seen = declared.observed_load ? CAN::Timing::Format.percent(declared.observed_load) : '-'
        "Bus load at #{rate}: #{seen} over the log (worst-case bit stuffing), " \
          "#{CAN::Timing::Format.percent(declared.declared_load)} declared\n"
      end

      def ms(seconds)
        seconds ? format('%.3f', (seconds * 1000).to_f) : '-'
      end

      def malformed(report)
        info = report.source['malformed']
        return unless info && info['count'].positive?

        shown = info['lines'].map { |l| "  #{report.source['log']}:#{l['line']}: #{l['message']}\n    #{l['text']}" }
        more = info['count'] - shown.size
        shown << "  ... and #{more} more" if more.positive?
        "Malformed lines: #{info['count']}\n#{shown.join("\n")}\n"
      end

      def count(rows)
        return 'none' if rows.empty?

        "#{Naming.count(rows.size, 'id')}, #{Naming.count(rows.sum(&:frames), 'frame')}"
      end

      def id_cells(report, row)
        [Frame.key_to_s(row.key), row.frames.to_s, time(report, row.first_time), time(report, row.last_time)]
      end

      def filter(filter)
        return format('%<id>03X/%<mask>03X', id: filter.id, mask: filter.mask) unless filter.extended?

        format('%<id>08X/%<mask>08X ext', id: filter.id, mask: filter.mask)
      end

      def time(report, value)
        value ? format('%.3f', Report.seconds(value - report.traffic.first_time)) : '-'
      end

      def number(value)
        value ? format('%.1f', value) : '-'
      end

      # Rows of cells in aligned columns; a row shorter than the header ends
      # with a note that spans the remaining columns.
      def table(head, rows, indent: '')
        widths = column_widths(head, rows)
        [head, *rows].map do |row|
          cells = row.each_with_index.map do |cell, i|
            next cell if row.size < head.size && i == row.size - 1

            RIGHT.include?(head[i]) ? cell.rjust(widths[i]) : cell.ljust(widths[i])
          end
          "#{indent}#{cells.join('  ').rstrip}\n"
        end.join
      end

      def column_widths(head, rows)
        widths = head.map(&:size)
        rows.each do |row|
          # A note spans columns: only the name before it counts for widths.
          row.first(row.size == head.size ? row.size : 1).each_with_index { |c, i| widths[i] = [widths[i], c.size].max }
        end
        widths
      end
    end
  end
end
