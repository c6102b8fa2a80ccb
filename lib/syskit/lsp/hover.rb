# frozen_string_literal: true

require 'syskit/doc/site'
require 'syskit/lsp/target'
require 'syskit/lsp/hover_text'

module Syskit
  module LSP
    # The text shown when the cursor rests on something of the app: what
    # the site's page of it says, in short and in Markdown. The facts come
    # from the site's views (Doc::ModelView, TaskModelView,
    # CompositionView) and its catalog (names, documentation, where
    # declared), so that the editor and the site never disagree.
    class Hover
      include HoverText

      attr_reader :app

      def initialize(app)
        @app = app
      end

      # The catalog of the site, made once: the app does not change under
      # a Hover (the server makes a new one when it reloads the app).
      def catalog
        @catalog ||= Doc::Catalog.new(app)
      end

      # The Markdown of what is at +line+/+character+ (0-based) of the
      # buffer +text+ of +path+, nil when the cursor is on nothing known.
      def at(path, text, line, character)
        target = Resolver.new(app, Cursor.new(path, text, line, character)).target
        target && markdown(target)
      end

      private

      def markdown(target)
        case target.kind
        when :model then model(target.object)
        when :task_library then task_library(target.object)
        when :device then device(target.object)
        when :definition then definition(target.object)
        when :deployment then deployment(target.object)
        when :port then port(target.object, target.owner)
        when :conf then conf_section(target.object, target.name)
        when :namespace then namespace(target.name)
        end
      end

      def model(object)
        entry = catalog.entry_for(object)
        return unnamed(object) unless entry

        view = entry.kind.view && entry.kind.key != :profile ? Doc.const_get(entry.kind.view).new(catalog, object) : nil
        body = send(:"#{entry.kind.key}_facts", view || object)
        [heading(entry), entry.doc.to_s.strip, *body, declared(entry.declared_at)].reject(&:empty?).join("\n\n")
      end

      # A model the site has no page for (one of syskit's own).
      def unnamed(object)
        "**#{object.name}**"
      end

      def heading(entry)
        origin = entry.origin ? " (from #{entry.origin})" : ''
        "**#{entry.kind.singular}** `#{entry.name}`#{origin}"
      end

      def task_library(library)
        tasks = library.tasks.values.map { |t| "`#{t.name}`" }
        ["**task library** `#{library.name}`", list('Task models', tasks), declared(Location.new(library.path, 0))]
          .reject(&:empty?).join("\n\n")
      end

      def device(device)
        kind = device.com_bus? ? 'bus' : 'device'
        owner = device.robot.profile&.name || device.robot.to_s
        ["**#{kind}** `#{device.name}` of `#{owner}`", device.doc.to_s.strip, device_facts_line(device),
         declared(device.declared_at)].reject(&:empty?).join("\n\n")
      end

      def device_facts_line(device)
        facts = []
        facts << "model `#{device.model.name}`" if device.model_resolved?
        facts << "driver `#{device.driver_model.component_model.name}`" if device.driver_resolved?
        facts << "through `#{device.bus.name}`" if device.bus
        facts << "with_conf #{device.conf.map { |c| "`#{c}`" }.join(', ')}"
        facts.join(' · ')
      end

      def definition(definition)
        model = definition.component_model || definition.models.first
        ["**definition** `#{definition.name}_def` of `#{definition.profile.name}`", definition.doc.to_s.strip,
         model ? "model `#{model.name}`" : '', declared(definition.declared_at)].reject(&:empty?).join("\n\n")
      end

      def deployment(deployment)
        tasks = deployment.task_activities.map { |t| "`#{t.name}` (`#{t.model.name}`)" }
        ["**deployment** `#{deployment.name}`", list('Tasks', tasks), declared(deployment.declared_at)]
          .reject(&:empty?).join("\n\n")
      end

      # A port of a composition's child, of the model that declares it.
      def port(port, owner)
        of = owner.is_a?(Models::CompositionChild) ? "child `#{owner.child_name}`" : "`#{owner.name}`"
        declarer = port.respond_to?(:owner) && port.owner.respond_to?(:name) ? " (`#{port.owner.name}`)" : ''
        ["**#{port.direction} port** `#{port.name}` of #{of}#{declarer}: `#{type_of(port)}`",
         declared(port.declared_at)].reject(&:empty?).join("\n\n")
      end

      # A module holding models: the models the site documents in it.
      def namespace(name)
        prefix = "#{name}::"
        inside = []
        catalog.each_entry do |entry|
          inside << "`#{entry.name.delete_prefix(prefix)}` (#{entry.kind.singular})" if entry.name.start_with?(prefix)
        end
        return if inside.empty?

        ["**namespace** `#{name}`", list('Models', inside.sort)].join("\n\n")
      end

      def conf_section(model, name)
        section = ConfSections.find(app, model, name)
        return "**configuration** `#{name}` of `#{model.name}`: not declared" unless section

        ["**#{section.kind}** `#{name}` of `#{model.name}`", list('Sets', section.what.map do |w|
          "`#{w}`"
        end), declared(section.location)]
          .reject(&:empty?).join("\n\n")
      end
    end
  end
end
