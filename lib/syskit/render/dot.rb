# frozen_string_literal: true

require 'syskit/render/output'

module Syskit
  module Render
    # The plan as a Graphviz graph: a box per task, grouped by deployment,
    # an edge per connection labelled with its ports and policy. Written as
    # Text is, a chunk at a time (see Output).
    module Dot
      extend Output

      module_function

      # Writes the graph to +io+; returns +io+.
      def write(plan, io)
        out = quote(plan.profile.to_s, +'digraph ') << " {\n"
        out << "  rankdir=LR;\n  node [shape=box, fontname=\"Helvetica\"];\n"
        out << "  edge [fontname=\"Helvetica\", fontsize=10];\n"
        plan.tasks.group_by(&:deployment).sort_by(&:first).each_with_index do |(deployment, tasks), i|
          Output.flush(cluster(deployment, tasks, i, out), io)
        end
        plan.connections.each { |c| Output.flush(edge(c, out), io) }
        io.write(out << "}\n")
        io
      end

      # Graphviz draws the tasks of one deployment (one process) together.
      def cluster(deployment, tasks, index, out)
        out << '  subgraph cluster_' << index.to_s << " {\n    label=\"deployment "
        escape(deployment, out) << "\";\n"
        tasks.each do |t|
          quote(t.name, out << '    ') << ' [label="'
          escape(t.model, escape(t.name, out) << NEWLINE) << "\"];\n"
        end
        out << "  }\n"
      end

      # The label: from port -> to port, then the policy.
      def edge(connection, out)
        quote(connection.from.task, out << '  ') << ' -> '
        quote(connection.to.task, out) << ' [label="'
        escape(connection.from.port, out) << ' -> '
        escape(connection.to.port, out) << NEWLINE
        Output.policy(connection.policy, out) << "\"];\n"
      end

      SPECIAL = /[\\"\n]/
      ESCAPES = { '\\' => '\\\\', '"' => '\\"', "\n" => '\\n' }.freeze
      # A line break inside a label.
      NEWLINE = '\\n'

      # +text+ as a double-quoted Graphviz string, appended to +out+.
      def quote(text, out)
        escape(text, out << '"') << '"'
      end

      # +text+ with Graphviz's escapes, appended to +out+.
      def escape(text, out)
        out << (text.match?(SPECIAL) ? text.gsub(SPECIAL, ESCAPES) : text)
      end
    end
  end
end
