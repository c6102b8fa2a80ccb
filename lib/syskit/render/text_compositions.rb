# frozen_string_literal: true

module Syskit
  module Render
    module Text
      # The compositions of a plan, for people: each root composition with
      # its model and action, its arguments, its children by role (a child
      # composition then follows, indented under its parent) and its
      # exported ports.
      #
      #   Compositions (1)
      #     arm_control  SyskitBasics::Compositions::ArmControl  (Base.arm_control_def, conf default)
      #       arguments   speed: 0.5
      #       controller  arm_control_controller
      #       arm         ur10
      #       exports     setpoint -> arm_control_controller.setpoint
      module Compositions
        module_function

        def write(plan, out, io)
          return out if plan.compositions.empty?

          children = plan.compositions.group_by(&:parent)
          out << "\nCompositions (#{plan.compositions.size})\n"
          (children[nil] || []).each { |root| Output.flush(tree(root, children, 1, out), io) }
          out
        end

        def tree(composition, children, depth, out)
          composition_text(composition, '  ' * depth, out)
          (children[composition.name] || []).each { |child| tree(child, children, depth + 1, out) }
          out
        end

        def composition_text(composition, indent, out)
          header(composition, out << indent)
          lines = rows(composition)
          width = lines.map { |title, _| title.size }.max.to_i + 2
          lines.each { |title, text| Text.pad(width - title.size, out << indent << '  ' << title) << text << "\n" }
          out
        end

        # "name  Model  (action, conf default)"
        def header(composition, out)
          out << composition.name << '  ' << composition.model << '  ('
          out << composition.action << ', ' if composition.action
          Text.list(composition.conf, out << 'conf ') << ")\n"
        end

        # [title, text] lines: its arguments, a line per child, its exports.
        def rows(composition)
          rows = []
          unless composition.arguments.empty?
            rows << ['arguments', composition.arguments.map { |k, v| Text.plain(v, "#{k}: ") }.join(', ')]
          end
          composition.children.each { |role, name| rows << [role, name] }
          composition.exports.each_with_index do |(port, endpoint), i|
            rows << [i.zero? ? 'exports' : '', "#{port} -> #{endpoint.task}.#{endpoint.port}"]
          end
          rows
        end
      end
    end
  end
end
