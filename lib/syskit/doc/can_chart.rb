# frozen_string_literal: true

require 'erb'
require 'syskit/can/timing/format'

module Syskit
  module Doc
    # A CAN bus's load drawn as SVG by the gem itself (no plotting library
    # in the browser): the share of the bus each device's frames take,
    # stacked on a 0-100 % bar with the warning level marked, and, when the
    # bus has a bitrate, each frame's worst-case response time as a share
    # of its deadline. Numbers are written with fixed decimals, so the same
    # plan gives the same bytes.
    class CanChart
      WIDTH = 720
      LABEL = 200
      BAR = WIDTH - LABEL - 120
      ROW = 22
      # Okabe and Ito's palette, told apart with most colour blindness.
      COLORS = %w[#0072b2 #e69f00 #009e73 #cc79a7 #56b4e9 #d55e00 #f0e442 #555555].freeze
      MISS = '#c62828'
      OK = '#2e7d32'

      # +bus+: a Plan::Bus; +timing+: its CAN::Timing::BusResult (nil
      # without a bitrate); +warn_above+: the load syskit check warns above.
      def initialize(bus, timing, warn_above: nil)
        @bus = bus
        @timing = timing
        @warn_above = warn_above
      end

      # The load chart, and the response-time chart when there is a timing.
      def to_svg
        return +'' unless @timing

        load_chart + response_chart
      end

      # Each device's share of the bus (sum of C/T of its frames).
      def device_loads
        @timing.frames.group_by { |r| r.frame.device.to_s }
               .map { |device, results| [device, results.sum(0r) { |r| r.transmission_time / r.frame.period }] }
               .sort_by { |device, load| [-load, device] }
      end

      private

      def load_chart
        loads = device_loads
        height = 72 + (loads.size * ROW)
        out = svg_open(height, "Load of bus #{@bus.name}: #{percent(@timing.utilization)} of its bitrate")
        out << text(0, 18, "load of #{@bus.name}, #{percent(@timing.utilization)} of " \
                           "#{CAN::Timing::Format.bitrate(@bus.bitrate)}", 'title')
        out << rect(LABEL, 36, BAR, 18, '#eef1f5', 'track')
        x = LABEL.to_r
        loads.each_with_index do |(_device, load), i|
          width = [load, 1 - ((x - LABEL) / BAR)].min * BAR
          out << rect(x, 36, width, 18, COLORS[i % COLORS.size], nil)
          x += width
        end
        out << text(LABEL - 8, 49, 'all devices', 'label end')
        out << text(LABEL + BAR + 6, 49, percent(@timing.utilization), 'value')
        out << marker(@warn_above) if @warn_above
        loads.each_with_index do |(device, load), i|
          y = 68 + (i * ROW)
          out << rect(LABEL, y, 12, 12, COLORS[i % COLORS.size], nil)
          out << text(LABEL + 18, y + 10, "#{device}  #{percent(load)}", 'label')
        end
        out << "</svg>\n"
      end

      # The warning level, a dashed line across the bar.
      def marker(level)
        x = LABEL + (BAR * [level, 1].min)
        %(<line class="warn" x1="#{num(x)}" y1="32" x2="#{num(x)}" y2="58" stroke="#b26a00" ) +
          %(stroke-dasharray="3 2"/>\n) + text(x + 3, 30, "warning level #{percent(level)}", 'note')
      end

      def response_chart
        frames = @timing.frames
        height = 40 + (frames.size * ROW) + 20
        out = svg_open(height, "Worst-case response time of each frame of bus #{@bus.name}, against its deadline")
        out << text(0, 18, 'worst-case response time, as a share of the deadline', 'title')
        frames.each_with_index do |result, i|
          y = 32 + (i * ROW)
          out << text(LABEL - 8, y + 12, "#{result.frame.hex_id} #{result.frame.device}", 'label end')
          out << rect(LABEL, y, BAR, 16, '#eef1f5', 'track')
          share = result.response_time ? result.response_time / result.frame.deadline : 1
          color = result.schedulable? ? OK : MISS
          out << rect(LABEL, y, [share, 1].min * BAR, 16, color, nil)
          out << text(LABEL + BAR + 6, y + 12, response_label(result), 'value')
        end
        axis = 32 + (frames.size * ROW) + 12
        out << text(LABEL, axis, '0', 'note') << text(LABEL + BAR, axis, 'deadline', 'note end')
        out << "</svg>\n"
      end

      def response_label(result)
        return 'unbounded' unless result.response_time

        "#{CAN::Timing::Format.ms_value(result.response_time)} / #{CAN::Timing::Format.ms(result.frame.deadline)}"
      end

      def svg_open(height, label)
        %(<svg class="chart" xmlns="http://www.w3.org/2000/svg" width="#{WIDTH}" height="#{height}" ) +
          %(viewBox="0 0 #{WIDTH} #{height}" role="img" aria-label="#{h(label)}">\n<title>#{h(label)}</title>\n)
      end

      def rect(x, y, width, height, fill, css)
        klass = css ? %( class="#{css}") : ''
        %(<rect#{klass} x="#{num(x)}" y="#{num(y)}" width="#{num(width)}" height="#{num(height)}" fill="#{fill}"/>\n)
      end

      def text(x, y, content, css)
        anchor = css.include?('end') ? ' text-anchor="end"' : ''
        %(<text class="#{css}" x="#{num(x)}" y="#{num(y)}"#{anchor}>#{h(content)}</text>\n)
      end

      def percent(fraction)
        CAN::Timing::Format.percent(fraction)
      end

      # One decimal, whatever the number's class (Rational, Float, Integer).
      def num(value)
        format('%.1f', value.to_f).delete_suffix('.0')
      end

      def h(text)
        ERB::Util.html_escape(text)
      end
    end
  end
end
