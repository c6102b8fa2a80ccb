# frozen_string_literal: true

require 'syskit/render/output'
require 'syskit/can/timing/format'
require 'syskit/render/dot_layout'

module Syskit
  module Render
    # The plan as a Graphviz graph, drawn as Syskit draws dataflow: each
    # task a record with its input ports on the left and its output ports on
    # the right, each connection an edge between two ports labelled with its
    # policy. A composition is a box holding the tasks that are its children
    # alone (a task several compositions share stays out), device drivers
    # included, its child compositions boxes inside. A bus is a box holding
    # its driver (drawn in blue, in bold) and the drivers of the devices
    # attached through it that no composition uses, a bus attached through
    # it being a box inside. Tasks that share a deployment (one process) are
    # in a dashed box when they are in the same box, and say their
    # deployment otherwise. The title is the profile and the robot.
    #
    # For the picture to stay readable: a task shows the ports the plan
    # connects (+all_ports: true+ for every port, a note says how many are
    # left out otherwise), a bus box its bitrate and load, a device its CAN
    # filter; the frames a device sends to its bus's driver are drawn from
    # the driver, the arrow turned back, each labelled with its policy, so
    # that the device is ranked after its driver instead of looped round
    # it; other connections into one input with one policy are labelled
    # once. Ranks are closer than graphviz's default and boxes titled
    # smaller than the plan, for the example app's plan to fit a 1,400 px
    # window.
    #
    # +links+ (task model name => URL) makes each task's box a link (the
    # documentation site links tasks to their model's page).
    #
    # Written as Text is, a chunk at a time (see Output).
    module Dot
      extend Output

      BUS_DRIVER = 'style="filled,bold", fillcolor="#cfe0f5", color="#2f5d95"'
      DEVICE_DRIVER = 'style=filled, fillcolor="#ffffff"'
      BUS_BOX = 'style="rounded,filled"; fillcolor="#f2f6fc"; color="#7a9cc6"'
      DEPLOYMENT_BOX = 'style="dashed,rounded"; color="#888888"'
      COMPOSITION_BOX = 'style="rounded,filled"; fillcolor="#f4f8ef"; color="#6b8e4e"'
      # Dataflow left to right, ranks closer than graphviz's default (0.5
      # inch): most of a plan's width is its records and the policies
      # between them, and the example app's plan then fits a 1,400 px
      # window. Boxes are titled smaller than the plan.
      LAYOUT = "  rankdir=LR;\n  ranksep=0.3;\n"
      BOX_FONT = 'fontsize=12'

      # Writes the graph of one plan.
      class Writer
        def initialize(plan, io, links: nil, all_ports: false)
          @plan = plan
          @io = io
          @links = links
          @out = Dot.quote(plan.profile.to_s, +'digraph ') << " {\n"
          @layout = Layout.new(plan)
          @ports = {} # task name => port name => record field
          @connected = connected_ports unless all_ports
          @filters = can_filters
          @labelled = {}
        end

        def write
          @out << '  label=' << Dot.quote("#{@plan.profile} on robot '#{@plan.robot}'", +'')
          @out << ";\n  labelloc=t;\n  fontname=\"Helvetica\";\n  fontsize=16;\n" << LAYOUT
          @out << "  node [shape=record, fontname=\"Helvetica\", fontsize=10];\n"
          @out << "  edge [fontname=\"Helvetica\", fontsize=9, color=\"#555555\"];\n"
          box(@layout.top, '  ')
          @plan.connections.each { |c| Output.flush(edge(c), @io) }
          @io.write(@out << "}\n")
          @io
        end

        private

        # The tasks of +box+ (grouped by shared deployment), then its buses'
        # boxes, each in a cluster subgraph.
        def box(box, indent)
          box.tasks.group_by(&:deployment).each { |deployment, tasks| deployment(deployment, tasks, indent) }
          box.boxes.each do |inner|
            cluster(inner.id, inner.label, inner.style, indent)
            box(inner, "#{indent}  ")
            @out << indent << "}\n"
          end
        end

        # Tasks of one deployment in a box: in a box of their own when there
        # are several, else each saying its deployment when the deployment
        # has tasks elsewhere.
        def deployment(name, tasks, indent)
          return tasks.each { |t| node(t, shared_note(name), indent) } if tasks.size == 1

          server = tasks.first.process_server
          label = server ? "deployment #{name} on #{Output.process_server(server)}" : "deployment #{name}"
          cluster("cluster_deployment_#{name}", label, DEPLOYMENT_BOX, indent)
          @in_deployment_box = true
          tasks.each { |task| node(task, nil, "#{indent}  ") }
          @in_deployment_box = false
          @out << indent << "}\n"
        end

        def shared_note(deployment)
          "deployment #{deployment}" if @layout.shared_deployments.key?(deployment)
        end

        def cluster(id, label, style, indent)
          Dot.quote(id, @out << indent << 'subgraph ') << " {\n"
          Dot.quote(label, @out << indent << '  label=') << '; ' << style << '; ' << BOX_FONT << ";\n"
        end

        # Task name => names of its connected ports.
        def connected_ports
          found = Hash.new { |h, k| h[k] = {} }
          @plan.connections.each do |c|
            found[c.from.task][c.from.port] = true
            found[c.to.task][c.to.port] = true
          end
          found
        end

        # Task name => the CAN filters of its devices ("id 0x181/0x7FF").
        def can_filters
          @plan.devices.each_with_object(Hash.new { |h, k| h[k] = [] }) do |d, found|
            id, mask = d.attributes['can_id']
            found[d.task] << "id #{Output.hex(id)}/#{Output.hex(mask || id)}" if id.is_a?(Integer)
          end
        end

        # A task as a record: {inputs | name, model | outputs}. Its ports'
        # record fields are kept for the edges.
        def node(task, note, indent)
          shown = shown_ports(task)
          inputs, outputs = shown.partition { |p| p.direction == 'input' }
          fields = @ports[task.name] = {}
          Dot.quote(task.name, @out << indent) << ' [label="{'
          port_fields(inputs, 'i', fields) << '|' unless inputs.empty?
          title(task, notes(task, note, task.ports.size - shown.size))
          port_fields(outputs, 'o', fields, '|') unless outputs.empty?
          Output.flush(style(task) << "];\n", @io)
        end

        # The middle of the record: name, model and notes.
        def title(task, notes)
          Dot.record(task.model, Dot.record(task.name, @out) << NEWLINE)
          notes.each { |line| Dot.record(line, @out << NEWLINE) }
        end

        def shown_ports(task)
          return task.ports unless @connected

          connected = @connected[task.name]
          task.ports.select { |port| connected[port.name] }
        end

        # Lines under a task's name: its deployment when shared, its CAN
        # filters, the ports left out.
        def notes(task, note, hidden)
          # A deployment's box says where it runs; a task alone says it.
          server = task.process_server && !@in_deployment_box && "on #{Output.process_server(task.process_server)}"
          lines = [note, server, *@filters[task.name]]
          lines << "+#{Naming.count(hidden, 'port')} not connected" if hidden.positive?
          lines.compact
        end

        # A bus driver is drawn apart from device drivers.
        def style(task)
          @out << '}", ' << (@layout.bus_tasks[task.name] ? BUS_DRIVER : DEVICE_DRIVER)
          url = @links && @links[task.model]
          url ? Dot.quote(task.model, Dot.quote(url, @out << ', URL=') << ', tooltip=') : @out
        end

        # {<i0> name|<i1> other}, after +separator+.
        def port_fields(list, prefix, fields, separator = '')
          @out << separator << '{'
          list.each_with_index do |port, i|
            field = "#{prefix}#{i}"
            fields[port.name] = field
            Dot.record(port.name, @out << (i.zero? ? '' : '|') << '<' << field << '> ')
          end
          @out << '}'
        end

        # From the output port's field to the input port's, labelled with
        # the policy (once per input port and policy).
        def edge(connection)
          from = connection.from
          to = connection.to
          return into_bus(connection) if @layout.on_bus?(from.task, to.task)

          endpoint(to, endpoint(from, @out << '  ') << ' -> ')
          key = [to.task, to.port, connection.policy]
          return @out << ";\n" if @labelled[key]

          @labelled[key] = true
          Output.policy(connection.policy, @out << ' [label="') << "\"];\n"
        end

        # The frames a device sends to its bus's driver. Written from the
        # driver with the arrow turned back, so that graphviz ranks the
        # device after its driver as the driver's writes to it do, instead
        # of looping the device round the driver: every such edge leaves
        # the driver's input from its left and reaches the device's output
        # from its right, each labelled with its own policy.
        def into_bus(connection)
          endpoint(connection.from, endpoint(connection.to, @out << '  ') << ' -> ')
          Output.policy(connection.policy, @out << ' [dir=back, label="') << "\"];\n"
        end

        def endpoint(endpoint, out)
          Dot.quote(endpoint.task, out)
          field = @ports.dig(endpoint.task, endpoint.port)
          field ? out << ':' << field : out
        end
      end

      module_function

      # Writes the graph to +io+; returns +io+.
      def write(plan, io, links: nil, all_ports: false)
        Writer.new(plan, io, links: links, all_ports: all_ports).write
      end

      SPECIAL = /[\\"\n]/
      ESCAPES = { '\\' => '\\\\', '"' => '\\"', "\n" => '\\n' }.freeze
      # Characters with a meaning in record labels, and Graphviz's own.
      RECORD_SPECIAL = /[\\"\n{}|<> ]/
      RECORD_ESCAPES = ESCAPES.merge('{' => '\\{', '}' => '\\}', '|' => '\\|', '<' => '\\<', '>' => '\\>',
                                     ' ' => '\\ ').freeze
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

      # +text+ as a field of a record label, appended to +out+.
      def record(text, out)
        text = text.to_s
        out << (text.match?(RECORD_SPECIAL) ? text.gsub(RECORD_SPECIAL, RECORD_ESCAPES) : text)
      end
    end
  end
end
