# frozen_string_literal: true

require 'syskit/can/timing/format'

module Syskit
  module Render
    module Dot
      # Where each task is drawn: the bus boxes (nested as the buses are),
      # the composition boxes (nested as the compositions are) and the
      # tasks at each level, computed once from the plan.
      class Layout
        # A cluster: its id, label and style, its tasks and inner boxes.
        Box = Struct.new(:id, :label, :style, :tasks, :boxes)

        attr_reader :top, :bus_tasks, :shared_deployments

        # Whether +task+ is attached through the bus whose driver is
        # +bus_task+ (its frames go to that driver).
        def on_bus?(task, bus_task)
          bus = @bus_tasks[bus_task]
          bus ? @attached.fetch(task, []).include?(bus) : false
        end

        def initialize(plan)
          devices = plan.devices.group_by(&:task)
          buses = plan.devices.select(&:com_bus).to_h { |d| [d.name, d] }
          @wires = plan.buses.to_h { |b| [b.name, b] }
          @bus_tasks = {} # bus driver's task => bus name
          @attached = {} # task => buses it is attached through
          @boxes = {}
          @top = Box.new(nil, nil, nil, [], [])
          boxes(plan, buses)
          plan.tasks.each { |task| place(task, devices[task.name] || [], buses) }
          @shared_deployments = shared(plan.tasks)
        end

        # The box a bus's driver and the devices through the bus are in.
        def box_of(bus_name, buses)
          @boxes[bus_name] ||= begin
            box = Box.new("cluster_bus_#{bus_name}", bus_label(bus_name), BUS_BOX, [], [])
            parent = buses[bus_name]&.bus
            (parent && buses[parent] ? box_of(parent, buses) : @top).boxes << box
            box
          end
        end

        private

        # The boxes of the buses and of the compositions, nested.
        def boxes(plan, buses)
          buses.each_value { |bus| box_of(bus.name, buses) }
          @owners = composition_owners(plan)
          plan.compositions.each { |c| composition_box(c, plan) }
        end

        # "bus can0", then its bitrate and load when it declares them.
        def bus_label(bus_name)
          wire = @wires[bus_name]
          return "bus #{bus_name}" unless wire&.bitrate

          load = wire.utilization ? ", load #{CAN::Timing::Format.percent(wire.utilization)}" : ''
          "bus #{bus_name}\n#{CAN::Timing::Format.bitrate(wire.bitrate)}#{load}"
        end

        # For each task, the compositions whose child it is.
        def composition_owners(plan)
          owners = Hash.new { |h, k| h[k] = [] }
          plan.compositions.each { |c| c.children.each_value { |name| owners[name] << c.name } }
          owners
        end

        def composition_box(composition, plan)
          @composition_boxes ||= {}
          @composition_boxes[composition.name] ||= begin
            # A specialization's name is long: its selection on a line of its own.
            model = composition.model.to_s.sub('/', "\n/")
            box = Box.new("cluster_composition_#{composition.name}", "#{composition.name}\n#{model}",
                          COMPOSITION_BOX, [], [])
            parent = composition.parent && plan.find_composition(composition.parent)
            (parent ? composition_box(parent, plan) : @top).boxes << box
            box
          end
        end

        # A bus's driver goes in the bus's box. Any other task goes in the
        # box of the composition it is the child of, when it is the child
        # of one only: a device's driver is drawn where it is used, its
        # connection to the bus driver saying which bus it is on. A
        # device's driver that no composition uses stays in the box of the
        # bus it is attached through; the rest are drawn at the top.
        def place(task, devices, buses)
          bus = devices.find(&:com_bus)
          @bus_tasks[task.name] = bus.name if bus
          @attached[task.name] = devices.filter_map(&:bus)
          return box_of(bus.name, buses).tasks << task if bus

          owners = @owners.fetch(task.name, [])
          return @composition_boxes[owners.first].tasks << task if owners.size == 1

          through = devices.map(&:bus).find { |b| b && buses[b] }
          (through ? box_of(through, buses) : @top).tasks << task
        end

        # Deployments of several tasks, those in one box being drawn as a
        # box of their own.
        def shared(tasks)
          tasks.group_by(&:deployment).select { |_, ts| ts.size > 1 }
        end
      end
    end
  end
end
