# frozen_string_literal: true

require 'syskit/render/dot'

module Syskit
  module Render
    # Graphs of a composition model, for its documentation: its dataflow
    # (each child a record with the ports the composition connects or
    # exports, each connection an edge with its policy, each exported port
    # a node at the boundary) and its hierarchy (the composition, its
    # children by role, child compositions expanded). +links+ (model name
    # => URL) make the boxes links.
    module CompositionDot
      module_function

      def dataflow(model, links: {})
        out = Dot.quote(model.short_name, +'digraph ') << " {\n  rankdir=LR;\n"
        out << "  node [shape=record, fontname=\"Helvetica\", fontsize=10];\n"
        out << "  edge [fontname=\"Helvetica\", fontsize=9, color=\"#555555\"];\n"
        used = used_ports(model)
        model.each_child { |name, child| child_node(name, child, used[name] || [], links, out) }
        model.exports.each_value { |export| export_node(export, out) }
        model.port_connections.each { |c| connection_edge(c, out) }
        out << "}\n"
      end

      def hierarchy(model, links: {})
        out = Dot.quote(model.short_name, +'digraph ') << " {\n  rankdir=TB;\n"
        out << '  node [shape=box, style="rounded,filled", fillcolor="#ffffff", fontname="Helvetica", ' \
               "fontsize=10];\n"
        out << "  edge [fontname=\"Helvetica\", fontsize=9, color=\"#6b8e4e\"];\n"
        tree(model, 'root', links, out, [])
        out << "}\n"
      end

      # The ports of each child that a connection or an export names.
      def used_ports(model)
        used = Hash.new { |h, k| h[k] = [] }
        ports = model.port_connections.flat_map { |c| [c.from, c.to] } + model.exports.each_value.map(&:port)
        ports.each { |p| used[p.child_name] << p unless used[p.child_name].any? { |u| u.name == p.name } }
        used
      end

      def child_node(name, child, ports, links, out)
        inputs, outputs = ports.sort_by(&:name).partition(&:input?)
        Dot.quote("child_#{name}", out << '  ') << ' [label="{'
        fields(inputs, 'i', out) << '|' unless inputs.empty?
        Dot.record(models_label(child), Dot.record(name, out) << Dot::NEWLINE)
        fields(outputs, 'o', out << '|') unless outputs.empty?
        out << '}"'
        link(child, links, out)
        out << ", style=filled, fillcolor=\"#{child.requirements.abstract? ? '#fff7e0' : '#ffffff'}\"];\n"
      end

      def fields(ports, prefix, out)
        out << '{'
        ports.each_with_index { |p, i| Dot.record(p.name, out << (i.zero? ? '' : '|') << "<#{prefix}_#{p.name}> ") }
        out << '}'
      end

      def models_label(child)
        child.models.map { |m| m.respond_to?(:short_name) ? m.short_name : m.to_s }.join(', ')
      end

      def link(child, links, out)
        url = child.models.filter_map { |m| links[m.name] }.first
        Dot.quote(url, out << ', URL=') if url
        out
      end

      def export_node(export, out)
        Dot.quote("export_#{export.name}", out << '  ')
        Dot.quote(export.name, out << ' [shape=cds, style=filled, fillcolor="#f4f8ef", label=') << "];\n"
        from, to = if export.port.input?
                     ["export_#{export.name}",
                      endpoint(export.port,
                               'i')]
                   else
                     [endpoint(export.port, 'o'), "export_#{export.name}"]
                   end
        out << '  ' << quoted_endpoint(from) << ' -> ' << quoted_endpoint(to) << " [style=dashed];\n"
      end

      def connection_edge(connection, out)
        out << '  ' << quoted_endpoint(endpoint(connection.from, 'o')) << ' -> '
        out << quoted_endpoint(endpoint(connection.to, 'i')) << ' [label="'
        policy = connection.policy
        Output.policy(policy.empty? ? Network::Policy::DATA : Network::Policy.of(policy), out) << "\"];\n"
      end

      def endpoint(port, prefix)
        ["child_#{port.child_name}", "#{prefix}_#{port.name}"]
      end

      def quoted_endpoint(endpoint)
        node, field = endpoint
        field ? Dot.quote(node, +'') << ':' << Dot.quote(field, +'') : Dot.quote(node, +'')
      end

      # The composition and its children; a child that is a composition
      # has its own children below it (each model once per branch).
      def tree(model, id, links, out, seen)
        Dot.quote(id, out << '  ') << ' [label=' << Dot.quote(model.short_name, +'')
        url = links[model.name]
        Dot.quote(url, out << ', URL=') if url
        out << ", fillcolor=\"#f4f8ef\"];\n"
        model.each_child do |name, child|
          tree_child(child, "#{id}.#{name}", links, out, seen + [model])
          Dot.quote(id, out << '  ') << ' -> ' << Dot.quote("#{id}.#{name}", +'')
          Dot.quote(name, out << ' [label=') << "];\n"
        end
        out
      end

      def tree_child(child, id, links, out, seen)
        component = child.requirements.component_model
        nested = component.is_a?(Class) && component <= Composition && !seen.include?(component)
        return tree(component, id, links, out, seen) if nested

        Dot.quote(id, out << '  ') << ' [label=' << Dot.quote(models_label(child), +'')
        link(child, links, out) << "];\n"
      end
    end
  end
end
