# frozen_string_literal: true

require 'syskit/render/output'
require 'syskit/can/timing/format'

module Syskit
  module Render
    # The plan for people reading a terminal.
    #
    # Everything is appended to one string, padding included, rather than
    # built from a formatted string per line: a plan of 10,000 devices has
    # some 700,000 lines. The string goes to the IO a chunk at a time (see
    # Output).
    module Text
      extend Output

      # The title column of a task's details, and its continuation lines.
      DETAIL_WIDTH = 16
      DEVICES = '    devices     '
      DEPENDS_ON = '    depends on  '
      PROPERTIES = '    properties  '
      PORTS = '    ports       '
      OPERATIONS = '    operations  '
      CONTINUED = (' ' * DETAIL_WIDTH).freeze
      STEP_WIDTH = 9
      # Padding up to this width is made once.
      SPACES = Array.new(80) { |width| (' ' * width).freeze }.freeze
      private_constant :SPACES

      module_function

      # Writes the plan to +io+; returns +io+.
      def write(plan, io)
        out = "Plan of #{plan.profile} on robot '#{plan.robot}'\n"
        out << "\nTasks (#{plan.tasks.size})\n"
        plan.tasks.each { |task| Output.flush(task_text(task, out), io) }
        out << "\nConnections (#{plan.connections.size})\n"
        connections_text(plan.connections, out, io)
        out << "\nOrder\n"
        order_text(plan.order, out, io)
        io.write(buses_text(plan.buses, out))
        io
      end

      # The CAN buses: bitrate and utilisation, then one line per declared
      # frame, in priority order.
      def buses_text(buses, out)
        return out if buses.empty?

        out << "\nBuses (#{buses.size})\n"
        buses.each do |bus|
          out << '  ' << bus.name << '  ' << bus_load(bus) << "\n"
          out << "    no frames declared\n" if bus.frames.empty?
          id_width = bus.frames.map { |f| f.extended ? 8 : 3 }.max
          device_width = bus.frames.map { |f| f.device.size }.max
          bus.frames.each { |f| frame_text(f, id_width, device_width, out) }
        end
        out
      end

      # "250 kbit/s, utilisation 3.1 %"
      def bus_load(bus)
        return 'no bitrate declared' unless bus.bitrate

        "#{CAN::Timing::Format.bitrate(bus.bitrate)}, utilisation #{CAN::Timing::Format.percent(bus.utilization)}"
      end

      # "    080  sync  0 bytes, period 10 ms, deadline 2 ms, jitter 0.1 ms"
      def frame_text(frame, id_width, device_width, out)
        id = format(frame.extended ? '%08X' : '%03X', frame.id)
        pad(id_width - id.size, out << '    ' << id) << '  '
        pad(device_width - frame.device.size, out << frame.device) << '  ' << frame.bytes.to_s
        out << (frame.bytes == 1 ? ' byte' : ' bytes')
        frame_times(frame).each { |what, value| out << ', ' << what << ' ' << CAN::Timing::Format.ms(value) }
        out << "\n"
      end

      # The period, and the deadline and jitter when they say more.
      def frame_times(frame)
        times = [['period', frame.period]]
        times << ['deadline', frame.deadline] if frame.deadline != frame.period
        times << ['jitter', frame.jitter] if frame.jitter.positive?
        times
      end

      # The task's line, its devices and dependencies, then its properties
      # and ports.
      def task_text(task, out)
        out << '  ' << task.name << '  ' << task.model << '  (deployment ' << task.deployment
        out << ', unmanaged' if task.unmanaged
        list(task.conf, out << ', conf ') << ")\n"
        list(task.devices, out << DEVICES) << "\n" unless task.devices.empty?
        list(task.depends_on, out << DEPENDS_ON) << "\n" unless task.depends_on.empty?
        details_text(task, out)
      end

      def details_text(task, out)
        details(PROPERTIES, task.properties, out) { |(name, value)| plain(value, out << name << ': ') }
        details(PORTS, task.ports, out) { |port| port_text(port, out) }
        details(OPERATIONS, task.operations, out) { |op| operation_text(op, out) }
        out
      end

      def port_text(port, out)
        out << port.name << '  ' << port.direction << ' ' << port.type
        port.dynamic ? out << ' (dynamic)' : out
      end

      # +watch("gps", 16, 255)+: the call as it was written.
      def operation_text(operation, out)
        out << operation.name << '('
        operation.arguments.each_with_index { |arg, i| plain(arg, i.zero? ? out : out << ', ') }
        out << ')'
      end

      # One line per entry, the title on the first.
      def details(title, entries, out)
        entries.each_with_index do |entry, i|
          out << (i.zero? ? title : CONTINUED)
          yield entry
          out << "\n"
        end
      end

      # Names separated by commas.
      def list(names, out)
        names.each_with_index { |name, i| (i.zero? ? out : out << ', ') << name }
        out
      end

      # Plain data written as compact JSON, without loading the json library
      # (whose Kernel#j would then be callable from user files).
      def plain(value, out)
        case value
        when Hash
          out << '{'
          value.each_with_index { |(k, v), i| plain(v, (i.zero? ? out : out << ',') << k.to_s.inspect << ':') }
          out << '}'
        when Array
          out << '['
          value.each_with_index { |v, i| plain(v, i.zero? ? out : out << ',') }
          out << ']'
        when String then out << value.inspect
        when nil then out << 'null'
        else out << value.to_s
        end
      end

      # Columns: from, to, type (padded to their widest entry), then policy.
      def connections_text(connections, out, io)
        widths = [connections.map { |c| width(c.from) }.max.to_i, connections.map { |c| width(c.to) }.max.to_i,
                  connections.map { |c| c.type.size }.max.to_i]
        connections.each { |c| Output.flush(connection_text(c, widths, out), io) }
        out
      end

      def connection_text(conn, (from, to, type), out)
        pad(from - width(conn.from), endpoint(conn.from, out << '  ')) << ' -> '
        pad(to - width(conn.to), endpoint(conn.to, out)) << '  ' << conn.type
        Output.policy(conn.policy, pad(type - conn.type.size, out) << '  ') << "\n"
      end

      # task.port
      def endpoint(endpoint, out)
        out << endpoint.task << '.' << endpoint.port
      end

      def width(endpoint)
        endpoint.task.size + endpoint.port.size + 1
      end

      # Numbered steps, numbers right-aligned.
      def order_text(order, out, io)
        width = order.size.to_s.size
        order.each_with_index do |step, i|
          number = (i + 1).to_s
          pad(width - number.size, out << '  ') << number << '. ' << step.step
          Output.flush(pad(STEP_WIDTH - step.step.size, out) << ' ' << step.task << "\n", io)
        end
        out
      end

      def pad(width, out)
        width.positive? ? out << (SPACES[width] || (' ' * width)) : out
      end
    end
  end
end
