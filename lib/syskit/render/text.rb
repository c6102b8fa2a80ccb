# frozen_string_literal: true

module Syskit
  module Render
    # The plan for people reading a terminal.
    module Text
      module_function

      def render(plan)
        out = "Plan of #{plan.profile} on robot '#{plan.robot}'\n"
        out << "\nTasks (#{plan.tasks.size})\n"
        plan.tasks.each { |task| out << task_text(task) }
        out << "\nConnections (#{plan.connections.size})\n"
        out << connections_text(plan.connections)
        out << "\nOrder\n"
        width = plan.order.size.to_s.size
        plan.order.each_with_index do |step, i|
          out << format("  %<i>#{width}d. %<step>-9s %<task>s\n", i: i + 1, step: step.step, task: step.task)
        end
        out
      end

      def task_text(task)
        out = "  #{task.name}  #{task.model}  (deployment #{task.deployment}, conf #{task.conf.join(', ')})\n"
        out << "    devices     #{task.devices.join(', ')}\n" unless task.devices.empty?
        out << "    depends on  #{task.depends_on.join(', ')}\n" unless task.depends_on.empty?
        out << block('properties', task.properties.map { |k, v| "#{k}: #{plain(v)}" })
        out << block('ports', task.ports.map do |p|
          "#{p.name}  #{p.direction} #{p.type}#{' (dynamic)' if p.dynamic}"
        end)
      end

      # Plain data written as compact JSON, without loading the json library
      # (whose Kernel#j would then be callable from user files).
      def plain(value)
        case value
        when Hash then "{#{value.map { |k, v| "#{k.to_s.inspect}:#{plain(v)}" }.join(',')}}"
        when Array then "[#{value.map { |v| plain(v) }.join(',')}]"
        when String then value.inspect
        when nil then 'null'
        else value.to_s
        end
      end

      def block(title, lines)
        return '' if lines.empty?

        lines.each_with_index.map do |line, i|
          format("    %-11<title>s %<line>s\n", title: i.zero? ? title : '', line: line)
        end.join
      end

      def connections_text(connections)
        rows = connections.map { |c| connection_row(c) }
        widths = (0..2).map { |i| rows.map { |r| r[i].size }.max.to_i }
        rows.map do |r|
          "  #{r[0].ljust(widths[0])} -> #{r[1].ljust(widths[1])}  #{r[2].ljust(widths[2])}  #{r[3]}\n"
        end.join
      end

      def connection_row(conn)
        ["#{conn.from.task}.#{conn.from.port}", "#{conn.to.task}.#{conn.to.port}", conn.type, policy_text(conn.policy)]
      end

      def policy_text(policy)
        policy['type'] == 'buffer' ? "buffer #{policy['size']}" : policy['type']
      end
    end
  end
end
