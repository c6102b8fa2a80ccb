# frozen_string_literal: true

module Syskit
  module LSP
    # The parts of a Hover's text for each kind of page of the site: the
    # facts its view gives, as short Markdown lists. Each +KIND_facts+
    # method takes the kind's view (the profile itself for a profile) and
    # returns paragraphs.
    module HoverText
      # How many items a list shows before "and N more".
      LIST_LIMIT = 12

      private

      def service_facts(view)
        [ports(view.ports), list('Provides', view.provides.map { |p| provided(p) }),
         list('Task models providing it', view.implementers.map { |i| "`#{i.task_model.name}`" })]
      end

      def device_facts(view)
        [ports(view.ports), list('Provides', view.provides.map { |p| provided(p) }),
         list('Drivers', view.implementers.map { |i| "`#{i.task_model.name}`" }),
         list('Devices', view.uses.flat_map { |u| u.devices.map { |d| "`#{d.name}`" } })]
      end

      def bus_facts(view)
        type = view.model.message_type
        [type ? "messages `#{type.name}`" : '', *device_facts(view)]
      end

      def task_model_facts(view)
        services = view.services.map { |s| "`#{s.name}` (`#{s.model.name}`)" }
        [view.parent ? "subclass of `#{view.parent.name}`" : '', ports(view.ports), list('Services', services),
         list('Properties', view.properties.map { |p| "`#{p.property.name}`" }),
         list('Drives', view.drives.flat_map { |u| u.devices.map { |d| "`#{d.name}`" } })]
      end

      def composition_facts(view)
        children = view.children.map { |c| "`#{c.child_name}`: #{c.models.map { |m| "`#{m.name}`" }.join(', ')}" }
        exports = view.exports.map { |e| "`#{e.name}` #{e.port.direction} `#{type_of(e.port)}`" }
        services = view.services.map { |s| "`#{s.name}`" }
        [list('Children', children), list('Exports', exports), list('Services', services)]
      end

      def profile_facts(profile)
        devices = profile.robot.each_master_device.map { |d| "`#{d.name}`" }
        [list('Devices', devices), list('Definitions', profile.definitions.keys.map { |n| "`#{n}_def`" })]
      end

      def ports(ports)
        list('Ports', ports.sort_by(&:name).map { |p| "`#{p.name}` #{p.direction} `#{type_of(p)}`" })
      end

      def provided(provided)
        mapped = provided.mappings.map { |theirs, ours| "#{theirs} → #{ours}" }
        "`#{provided.model.name}`#{" (#{mapped.join(', ')})" unless mapped.empty?}"
      end

      # A port's type as written, and what it stands for when a typedef.
      def type_of(port)
        port.respond_to?(:type_description) ? port.type_description : port.type.name
      end

      # "Title: a, b" as a paragraph, or a bulleted list when long; empty
      # without items.
      def list(title, items)
        return '' if items.empty?

        shown = items.first(LIST_LIMIT)
        shown << "and #{items.size - LIST_LIMIT} more" if items.size > LIST_LIMIT
        return "#{title}: #{shown.join(', ')}" if shown.sum(&:size) < 80

        "#{title}:\n#{shown.map { |i| "- #{i}" }.join("\n")}"
      end

      # Where it was declared, relative to its bundle.
      def declared(location)
        return '' unless location&.path

        root = app.bundle_roots.find { |r| location.path.start_with?("#{r}/") }
        "Declared at `#{location.to_s(root)}`"
      end
    end
  end
end
