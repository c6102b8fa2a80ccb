# frozen_string_literal: true

require 'syskit/render/output'
require 'syskit/can/timing/format'
require 'syskit/render/text_compositions'

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
        Compositions.write(plan, out, io)
        out << "\nTasks (#{plan.tasks.size})\n"
        plan.tasks.each { |task| Output.flush(task_text(task, out), io) }
        out << "\nConnections (#{plan.connections.size})\n"
        connections_text(plan.connections, out, io)
        out << "\nOrder\n"
        order_text(plan.order, out, io)
        io.write(buses_text(plan, out, io))
        io
      end

      # Each bus, with its driver, then the devices attached through it
      # (a bus attached through it followed by its own devices, indented),
      # then for a CAN bus its bitrate, utilisation and declared frames.
      def buses_text(plan, out, io)
        buses = plan.devices.select(&:com_bus)
        return out if buses.empty? && plan.buses.empty?

        # Looked up per bus: indexed once (a 10,000-device plan has 300 buses).
        lookup = { attached: plan.devices.group_by(&:bus), tasks: plan.tasks.to_h { |t| [t.name, t] },
                   cans: plan.buses.to_h { |b| [b.name, b] } }
        names = buses.to_h { |b| [b.name, true] }
        out << "\nBuses (#{buses.size})\n"
        buses.reject { |b| names[b.bus] }.each { |bus| Output.flush(bus_text(bus, lookup, out), io) }
        out
      end

      # A bus that is attached through no other: its header, load, devices
      # (a bus among them followed by its own) and frames.
      def bus_text(bus, lookup, out)
        bus_header(bus, lookup[:tasks][bus.task], out)
        can = lookup[:cans][bus.name]
        out << '    ' << bus_load(can) << "\n" if can
        attached_text(attached_tree(bus.name, lookup[:attached], 0), out)
        can ? frames_text(can, out) : out
      end

      # "  can0  CommonModels::Devices::Bus::CAN, driven by can0 (canbus::Task)"
      def bus_header(bus, task, out)
        out << '  ' << bus.name << '  ' << bus.model
        out << ', driven by ' << task.name << ' (' << task.model << ')' if task
        out << "\n"
      end

      # [device, depth] pairs: the devices through +bus+, each bus among them
      # followed by its own.
      def attached_tree(bus, attached, depth)
        (attached[bus] || []).flat_map do |device|
          [[device, depth], *(device.com_bus ? attached_tree(device.name, attached, depth + 1) : [])]
        end
      end

      # One line per attached device: name, model and CAN filter, in columns.
      def attached_text(tree, out)
        return out << "    no device attached\n" if tree.empty?

        out << "    devices\n"
        widths = [tree.map { |d, depth| (depth * 2) + d.name.size }.max, tree.map { |d, _| d.model.size }.max]
        tree.each { |device, depth| attached_line(device, depth, widths, out) }
        out
      end

      def attached_line(device, depth, (name_width, model_width), out)
        pad(depth * 2, out << '      ')
        pad(name_width - (depth * 2) - device.name.size, out << device.name) << '  '
        return out << device.model << "\n" if device.attributes.empty?

        pad(model_width - device.model.size, out << device.model)
        attributes_text(device.attributes, out) << "\n"
      end

      # "  id 0x1234 mask 0xFFFF", other attributes as name: value.
      def attributes_text(attributes, out)
        attributes.each do |name, value|
          if name == 'can_id' && value.is_a?(Array) && value.size == 2
            out << '  id ' << Output.hex(value[0]) << ' mask ' << Output.hex(value[1])
          else
            plain(value, out << '  ' << name << ': ', ids: Output.id_name?(name))
          end
        end
        out
      end

      # One line per frame declared on the CAN bus, in priority order.
      def frames_text(bus, out)
        return out << "    no frames declared\n" if bus.frames.empty?

        out << "    frames\n"
        id_width = bus.frames.map { |f| f.extended ? 8 : 3 }.max
        device_width = bus.frames.map { |f| f.device.size }.max
        bus.frames.each { |f| frame_text(f, id_width, device_width, out) }
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
        pad(id_width - id.size, out << '      ' << id) << '  '
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

      # Its deployment, where it runs when the robot says, and whether
      # Syskit manages it.
      def deployment_text(task, out)
        out << task.deployment
        out << ' on ' << Output.process_server(task.process_server) if task.process_server
        task.unmanaged ? out << ', unmanaged' : out
      end

      # The task's line, its devices and dependencies, then its properties
      # and ports.
      def task_text(task, out)
        deployment_text(task, out << '  ' << task.name << '  ' << task.model << '  (deployment ')
        list(task.conf, out << ', conf ') << ")\n"
        list(task.devices, out << DEVICES) << "\n" unless task.devices.empty?
        list(task.depends_on, out << DEPENDS_ON) << "\n" unless task.depends_on.empty?
        details_text(task, out)
      end

      def details_text(task, out)
        details(PROPERTIES, task.properties, out) { |(name, value)| property_text(name, value, out) }
        details(PORTS, task.ports, out) { |port| port_text(port, out) }
        details(OPERATIONS, task.operations, out) { |op| operation_text(op, out) }
        out
      end

      def port_text(port, out)
        out << port.name << '  ' << port.direction << ' '
        out << port.declared_type << ' (= ' << port.type << ')' if port.declared_type
        out << port.type unless port.declared_type
        port.dynamic ? out << ' (dynamic)' : out
      end

      # +watch("gps", 0x10, 0xFF)+: the call as it was written, ids in hex.
      def operation_text(operation, out)
        out << operation.name << '('
        names = operation.argument_names || []
        operation.arguments.each_with_index do |arg, i|
          plain(arg, i.zero? ? out : out << ', ', ids: Output.id_name?(names[i]))
        end
        out << ')'
      end

      # Lines are kept under this width where a value allows it.
      WRAP = 100

      # name: value, the value compact; a list or hash too long for one
      # line gets one line per element.
      def property_text(name, value, out)
        start = out.bytesize
        ids = Output.id_name?(name)
        plain(value, out << name << ': ', ids: ids)
        # Properties start at the details' column.
        return out if DETAIL_WIDTH + out.bytesize - start <= WRAP || !(value.is_a?(Array) || value.is_a?(Hash)) ||
                      value.size < 2

        out.replace(out.byteslice(0, start)) << name << ': '
        value.is_a?(Hash) ? plain_hash(value, out, ids, WRAPPED) : plain_array(value, out, ids, WRAPPED)
      end

      # How a list or hash is laid out: what follows its opening, separates
      # its elements and precedes its closing. Wrapped: one element per
      # line, indented under the property's name.
      COMPACT = ['', ',', ''].freeze
      WRAPPED = ["\n#{CONTINUED}  ", ",\n#{CONTINUED}  ", "\n#{CONTINUED}"].freeze

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
      # (whose Kernel#j would then be callable from user files); integers in
      # hex where +ids+ says they are CAN ids or masks (the values of an id
      # property, or of an id field of a hash).
      def plain(value, out, ids: false)
        case value
        when Hash then plain_hash(value, out, ids)
        when Array then plain_array(value, out, ids)
        when String then out << value.inspect
        when nil then out << 'null'
        when Integer then out << (ids ? Output.hex(value) : value.to_s)
        else out << value.to_s
        end
      end

      def plain_hash(hash, out, ids, layout = COMPACT)
        first, between, last = layout
        out << '{' << first
        hash.each_with_index do |(k, v), i|
          plain(v, (i.zero? ? out : out << between) << k.to_s.inspect << ':', ids: ids || Output.id_name?(k))
        end
        out << last << '}'
      end

      def plain_array(array, out, ids, layout = COMPACT)
        first, between, last = layout
        out << '[' << first
        array.each_with_index { |v, i| plain(v, i.zero? ? out : out << between, ids: ids) }
        out << last << ']'
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
