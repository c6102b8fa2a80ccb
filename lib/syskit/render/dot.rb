# frozen_string_literal: true

module Syskit
  module Render
    # The plan as a Graphviz graph: a box per task, grouped by deployment,
    # an edge per connection labelled with its ports and policy.
    module Dot
      module_function

      def render(plan)
        out = "digraph #{quote(plan.profile.to_s)} {\n"
        out << "  rankdir=LR;\n  node [shape=box, fontname=\"Helvetica\"];\n  edge [fontname=\"Helvetica\", fontsize=10];\n"
        plan.tasks.group_by(&:deployment).sort.each_with_index do |(deployment, tasks), i|
          out << "  subgraph cluster_#{i} {\n    label=#{quote("deployment #{deployment}")};\n"
          tasks.each do |t|
            out << "    #{quote(t.name)} [label=#{quote("#{t.name}\n#{t.model}")}];\n"
          end
          out << "  }\n"
        end
        plan.connections.each do |c|
          policy = c.policy['type'] == 'buffer' ? "buffer #{c.policy['size']}" : c.policy['type']
          label = "#{c.from.port} -> #{c.to.port}\n#{policy}"
          out << "  #{quote(c.from.task)} -> #{quote(c.to.task)} [label=#{quote(label)}];\n"
        end
        out << "}\n"
      end

      def quote(text)
        "\"#{text.gsub('\\', '\\\\\\\\').gsub('"', '\\"').gsub("\n", '\\n')}\""
      end
    end
  end
end
