# frozen_string_literal: true

require 'stringio'
require 'syskit/render/svg'
require 'syskit/can/timing'
require 'syskit/can/timing/format'
require 'syskit/can/timing/table'
require 'syskit/doc/can_chart'

module Syskit
  module Doc
    # What the page of a profile shows: its robot's devices and buses, and
    # the plan the generator returns for it on the site's robot: drawn
    # (Graphviz's dot, each task a link to its model's page), its tasks,
    # and for each CAN bus with declared frames their worst-case timing
    # and a chart of the bus's load. It never plans by itself: the plan is
    # Network::Generator's, the timing CAN::Timing::Analysis's.
    class ProfileView
      # A CAN bus of the plan, its timing (nil without a bitrate) and the
      # robot's declaration of it.
      CanBus = Struct.new(:bus, :timing, :device)

      # +apart+: see Network::ProfilePlan#apart (the plan is then the
      # devices').
      attr_reader :profile, :catalog, :robot, :plan, :error, :apart

      # +dot+: the path of Graphviz's dot, nil when it is not installed.
      def initialize(catalog, profile, robot:, dot:)
        @catalog = catalog
        @profile = profile
        @robot = robot
        @dot = dot
        @plan = nil
        @error = nil
        generate
      end

      def devices
        profile.robot.each_master_device.to_a
      end

      # The profile's definitions (see Profile::Definitions), by name.
      def definitions
        profile.definitions.values
      end

      # What a definition selects for the children of its composition,
      # as [key, selected] pairs: the key's name, and the device selected
      # (a Robot::MasterDeviceInstance) or the name of what is.
      def selections(definition)
        injection = definition.selections
        explicit = injection.explicit.map { |k, v| [k.is_a?(String) ? k : k.to_s, selected(v)] }
        explicit + injection.defaults.map { |v| ['(default)', selected(v)] }
      end

      def selected(value)
        device = value.device if value.is_a?(InstanceRequirements)
        device || (value.respond_to?(:short_name) ? value.short_name : value.to_s)
      end

      # What the robot block sets on a device, as [name, HTML] pairs: its
      # bus attributes (CAN filters in hex), configuration sections,
      # deployment preferences, timing and declared traffic.
      def settings(device)
        list = device.dsl_attributes.map { |name, v| [name.to_s, code(Render::Text.plain(v, +'', ids: true))] }
        if device.conf != Robot::MasterDeviceInstance::DEFAULT_CONF
          list << ['with_conf', device.conf.map { |c| code(c) }.join(', ')]
        end
        unless device.deployment_hints.empty?
          list << ['prefer_deployed_tasks', device.deployment_hints.map { |d| code(d.inspect) }.join(', ')]
        end
        list.concat(timing_settings(device))
      end

      # The plan drawn as SVG, to be put in the page as is (without the
      # XML prolog); nil when there is no plan or no dot.
      def graph_svg
        return unless plan && @dot

        @graph_svg ||= begin
          links = catalog.entries(:task_model).to_h { |e| [e.name, yield(e)] }
          svg = Render::Svg.write(plan, StringIO.new(+''), dot: @dot, links: links).string
          svg.sub(/\A.*?(?=<svg\b)/m, '')
        end
      end

      def dot?
        !@dot.nil?
      end

      # The CAN buses of the plan that carry declared frames.
      def can_buses
        return [] unless plan

        plan.buses.reject { |b| b.frames.empty? }.map do |bus|
          timing = bus.bitrate && CAN::Timing::Analysis.run(bitrate: bus.bitrate, frames: timing_frames(bus))
          CanBus.new(bus, timing, profile.robot.find_device(bus.name))
        end
      end

      # The chart of a bus's load, as SVG.
      def chart(can_bus)
        CanChart.new(can_bus.bus, can_bus.timing, warn_above: can_bus.device&.warn_above).to_svg
      end

      def format
        CAN::Timing::Format
      end

      private

      def h(text)
        ERB::Util.html_escape(text.to_s)
      end

      def code(text)
        "<code>#{h(text)}</code>"
      end

      def timing_settings(device)
        list = %i[period burst sample_size].filter_map do |name|
          value = device.public_send(name)
          [name.to_s, h(name == :period ? format.ms(value) : value.to_s)] if value
        end
        list << ['bitrate', h(format.bitrate(device.bitrate))] if device.com_bus? && device.bitrate
        frames = device.can_frames.size
        list << ['frame', h(Naming.count(frames, 'frame'))] if frames.positive?
        list
      end

      def generate
        result = Network::ProfilePlan.new(catalog.app, profile, robot: robot)
        @plan = result.plan
        @apart = result.apart
      rescue Syskit::Error => e
        @error = e.is_a?(ErrorList) ? e.errors : [e]
      end

      def timing_frames(bus)
        bus.frames.map do |f|
          CAN::Timing::Frame.new(id: f.id, extended: f.extended, bytes: f.bytes, period: f.period,
                                 deadline: f.deadline, jitter: f.jitter, device: f.device)
        end
      end
    end
  end
end
