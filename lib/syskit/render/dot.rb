# frozen_string_literal: true

module Syskit
  module Render
    # The plan as a Graphviz graph: a box per task, grouped by deployment,
    # an edge per connection labelled with its ports and policy.
    module Dot
      module_function

      def render(plan)
        out = "digraph #{quote(plan.profile.to_s)} {\n"
        out << "  rankdir=LR;\n  node [shape=box, fontname=\"Helvetica\"];\n"
        out << "  edge [fontname=\"Helvetica\", fontsize=10];\n"
        plan.tasks.group_by(&:deployment).sort.each_with_index do |(deployment, tasks), i|
          out << cluster(deployment, tasks, i)
        end
        plan.connections.each { |c| out << edge(c) }
        out << "}\n"
      end

      # Graphviz draws the tasks of one deployment (one process) together.
      def cluster(deployment, tasks, index)
        out = "  subgraph cluster_#{index} {\n    label=#{quote("deployment #{deployment}")};\n"
        tasks.each do |t|
          out << "    #{quote(t.name)} [label=#{quote("#{t.name}\n#{t.model}")}];\n"
        end
        out << "  }\n"
      end

      def edge(connection)
        policy = connection.policy
        policy = policy['type'] == 'buffer' ? "buffer #{policy['size']}" : policy['type']
        label = "#{connection.from.port} -> #{connection.to.port}\n#{policy}"
        "  #{quote(connection.from.task)} -> #{quote(connection.to.task)} [label=#{quote(label)}];\n"
      end

      def quote(text)
        "\"#{text.gsub('\\', '\\\\\\\\').gsub('"', '\\"').gsub("\n", '\\n')}\""
      end
    end
  end
end
