# frozen_string_literal: true

module Syskit
  module Render
    # The plan for people reading a terminal.
    #
    # Everything is appended to one string, padding included, rather than
    # built from a formatted string per line: a plan of 10,000 devices has
    # some 700,000 lines.
    module Text
      # The title column of a task's details, and its continuation lines.
      DETAIL_WIDTH = 16
      DEVICES = '    devices     '
      DEPENDS_ON = '    depends on  '
      PROPERTIES = '    properties  '
      PORTS = '    ports       '
      CONTINUED = (' ' * DETAIL_WIDTH).freeze
      STEP_WIDTH = 9

      module_function

      def render(plan)
        out = +"Plan of #{plan.profile} on robot '#{plan.robot}'\n"
        out << "\nTasks (#{plan.tasks.size})\n"
        plan.tasks.each { |task| task_text(task, out) }
        out << "\nConnections (#{plan.connections.size})\n"
        connections_text(plan.connections, out)
        out << "\nOrder\n"
        order_text(plan.order, out)
      end

      def task_text(task, out)
        out << '  ' << task.name << '  ' << task.model << '  (deployment ' << task.deployment << ', conf '
        list(task.conf, out) << ")\n"
        list(task.devices, out << DEVICES) << "\n" unless task.devices.empty?
        list(task.depends_on, out << DEPENDS_ON) << "\n" unless task.depends_on.empty?
        details(PROPERTIES, task.properties, out) { |(name, value)| plain(value, out << name << ': ') }
        details(PORTS, task.ports, out) do |port|
          out << port.name << '  ' << port.direction << ' ' << port.type
          out << ' (dynamic)' if port.dynamic
        end
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
      def connections_text(connections, out)
        from = connections.map { |c| c.from.task.size + c.from.port.size + 1 }.max.to_i
        to = connections.map { |c| c.to.task.size + c.to.port.size + 1 }.max.to_i
        type = connections.map { |c| c.type.size }.max.to_i
        connections.each do |c|
          out << '  ' << c.from.task << '.' << c.from.port
          pad(from - c.from.task.size - c.from.port.size - 1, out) << ' -> ' << c.to.task << '.' << c.to.port
          pad(to - c.to.task.size - c.to.port.size - 1, out) << '  ' << c.type
          policy(c.policy, pad(type - c.type.size, out) << '  ') << "\n"
        end
        out
      end

      def policy(policy, out)
        policy['type'] == 'buffer' ? out << 'buffer ' << policy['size'].to_s : out << policy['type']
      end

      # Numbered steps, numbers right-aligned.
      def order_text(order, out)
        width = order.size.to_s.size
        order.each_with_index do |step, i|
          number = (i + 1).to_s
          pad(width - number.size, out << '  ') << number << '. ' << step.step
          pad(STEP_WIDTH - step.step.size, out) << ' ' << step.task << "\n"
        end
        out
      end

      # Padding up to this width is made once.
      SPACES = Array.new(80) { |width| (' ' * width).freeze }.freeze
      private_constant :SPACES

      def pad(width, out)
        width.positive? ? out << (SPACES[width] || ' ' * width) : out
      end
    end
  end
end
