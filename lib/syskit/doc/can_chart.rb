# frozen_string_literal: true

require 'syskit/can/timing/format'
require 'syskit/doc/svg_writer'

module Syskit
  module Doc
    # A CAN bus's load drawn as SVG by the gem itself (no plotting library
    # in the browser): the share of the bus each device's frames take,
    # stacked on a 0-100 % bar with the warning level marked, and each
    # frame's worst-case response time as a share of its deadline.
    class CanChart
      WIDTH = 720
      # Where bars start (labels are on their left) and their length.
      LABEL = 200
      BAR = WIDTH - LABEL - 120
      ROW = 22
      TRACK = '#eef1f5'
      # Okabe and Ito's palette, told apart with most colour blindness.
      COLORS = %w[#0072b2 #e69f00 #009e73 #cc79a7 #56b4e9 #d55e00 #f0e442 #555555].freeze
      MISS = '#c62828'
      OK = '#2e7d32'
      WARN = '#b26a00'

      # +bus+: a Plan::Bus; +timing+: its CAN::Timing::BusResult;
      # +warn_above+: the load syskit check warns above (nil: not drawn).
      def initialize(bus, timing, warn_above: nil)
        @bus = bus
        @timing = timing
        @warn_above = warn_above
      end

      # Both charts, one after the other.
      def to_svg
        load_chart + response_chart
      end

      # [device, share of the bus] by decreasing share (sum of C/T of its
      # frames).
      def device_loads
        @timing.frames.group_by { |r| r.frame.device.to_s }
               .map { |device, results| [device, results.sum(0r) { |r| r.transmission_time / r.frame.period }] }
               .sort_by { |device, load| [-load, device] }
      end

      private

      def load_chart
        loads = device_loads
        title = "load of #{@bus.name}, #{percent(@timing.utilization)} of #{Format.bitrate(@bus.bitrate)}"
        svg = SvgWriter.new(WIDTH, 72 + (loads.size * ROW), title)
        svg.text([0, 18], title, 'title')
        stacked_bar(svg, loads)
        warning_level(svg) if @warn_above
        loads.each_with_index do |(device, load), i|
          y = 68 + (i * ROW)
          svg.rect([LABEL, y], [12, 12], color(i))
          svg.text([LABEL + 18, y + 10], "#{device}  #{percent(load)}", 'label')
        end
        svg.to_s
      end

      # One segment per device, in the order of the legend.
      def stacked_bar(svg, loads)
        svg.rect([LABEL, 36], [BAR, 18], TRACK, css: 'track')
        drawn = 0r
        loads.each_with_index do |(_device, load), i|
          width = [load, 1 - drawn].min
          svg.rect([LABEL + (drawn * BAR), 36], [width * BAR, 18], color(i))
          drawn += width
        end
        svg.text([LABEL - 8, 49], 'all devices', 'label end')
        svg.text([LABEL + BAR + 6, 49], percent(@timing.utilization), 'value')
      end

      def warning_level(svg)
        x = LABEL + (BAR * [@warn_above, 1].min)
        svg.dashed(x, 32, 58, WARN)
        svg.text([x + 3, 30], "warning level #{percent(@warn_above)}", 'note')
      end

      def response_chart
        frames = @timing.frames
        svg = SvgWriter.new(WIDTH, 60 + (frames.size * ROW),
                            "Worst-case response time of each frame of bus #{@bus.name}, against its deadline")
        svg.text([0, 18], 'worst-case response time, as a share of the deadline', 'title')
        frames.each_with_index { |result, i| response_bar(svg, result, 32 + (i * ROW)) }
        axis = 44 + (frames.size * ROW)
        svg.text([LABEL, axis], '0', 'note').text([LABEL + BAR, axis], 'deadline', 'note end')
        svg.to_s
      end

      def response_bar(svg, result, top)
        frame = result.frame
        share = result.response_time ? [result.response_time / frame.deadline, 1].min : 1
        svg.text([LABEL - 8, top + 12], "#{frame.hex_id} #{frame.device}", 'label end')
        svg.rect([LABEL, top], [BAR, 16], TRACK, css: 'track')
        svg.rect([LABEL, top], [share * BAR, 16], result.schedulable? ? OK : MISS)
        svg.text([LABEL + BAR + 6, top + 12], response_label(result), 'value')
      end

      # "0.805 / 1 ms": the worst-case response time and the deadline.
      def response_label(result)
        return 'unbounded' unless result.response_time

        "#{Format.ms_value(result.response_time)} / #{Format.ms(result.frame.deadline)}"
      end

      def color(index)
        COLORS[index % COLORS.size]
      end

      def percent(fraction)
        Format.percent(fraction)
      end

      Format = CAN::Timing::Format
      private_constant :Format
    end
  end
end
