# frozen_string_literal: true

require 'syskit/render/output'

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
        io.write(order_text(plan.order, out, io))
        io
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
        out
      end

      def port_text(port, out)
        out << port.name << '  ' << port.direction << ' ' << port.type
        port.dynamic ? out << ' (dynamic)' : out
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
