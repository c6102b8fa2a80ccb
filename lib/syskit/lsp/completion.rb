# frozen_string_literal: true

require 'syskit/doc/catalog'
require 'syskit/lsp/target'

module Syskit
  module LSP
    # What may be typed at the cursor, by what the line says before it:
    #
    #   device(|  com_bus(|          device (bus) models of the app
    #   through '|                   the buses of the file's profiles
    #   using_task_library '|        the task libraries on the search path
    #   .with_conf('default', '|     the sections of the configuration file
    #                                of the driver of the device above
    #   x_port.connect_to |          the ports of the composition's children
    #   x_child.|                    the ports of the child x
    #   OroGen.|  OroGen.lib.|       the loaded task libraries, their tasks
    #   use_deployment '|            the deployments of the loaded libraries
    #
    # Items are Hashes: label, kind (the protocol's CompletionItemKind),
    # detail and documentation.
    class Completion
      # The protocol's CompletionItemKind values used here.
      KINDS = { field: 5, variable: 6, class: 7, interface: 8, module: 9, value: 12 }.freeze

      CONTEXTS = [
        [/\b(device|com_bus)\s*\(?\s*(?:[\w:]*)\z/, :models],
        [/\bthrough\s*\(?\s*['"]\w*\z/, :buses],
        [/\busing_task_library\s*\(?\s*['"]\w*\z/, :libraries],
        [/\buse_deployment\s*\(?\s*['"]\w*\z/, :deployments],
        [/\bwith_conf\s*\(?(?:\s*['"][^'"]*['"]\s*,)*\s*['"]\w*\z/, :sections],
        [/\bconnect_to\s*\(?\s*\w*\z/, :sinks],
        [/\b(\w+)_child\.\w*\z/, :child_ports],
        [/\bOroGen\.(\w+)\.\w*\z/, :orogen_tasks],
        [/\bOroGen\.\w*\z/, :orogen_libraries]
      ].freeze

      attr_reader :app

      def initialize(app)
        @app = app
      end

      def catalog
        @catalog ||= Doc::Catalog.new(app)
      end

      # The items for +line+/+character+ (0-based) of the buffer +text+ of
      # +path+; empty where nothing is completed.
      def at(path, text, line, character)
        resolver = Resolver.new(app, Cursor.new(path, text, line, character))
        before = resolver.cursor.before
        CONTEXTS.each do |pattern, kind|
          match = pattern.match(before)
          return send(kind, resolver, match) if match
        end
        []
      end

      private

      def item(label, kind, detail, documentation = nil)
        { label: label, kind: KINDS.fetch(kind), detail: detail, documentation: documentation.to_s }
      end

      # Device models for device(, bus models for com_bus(, named as the
      # file may write them (the shortest name its modules resolve).
      def models(resolver, match)
        key = match[1] == 'com_bus' ? :bus : :device
        catalog.entries(key).map do |entry|
          item(short_name(resolver, entry.object), :class, entry.kind.singular, entry.summary)
        end
      end

      def short_name(resolver, model)
        parts = model.name.split('::')
        (1...parts.size).reverse_each do |drop|
          candidate = parts.drop(drop).join('::')
          return candidate if resolver.constant(candidate).equal?(model)
        end
        model.name
      end

      def buses(resolver, _match)
        resolver.profiles.flat_map { |p| p.robot.each_master_device.select(&:com_bus?) }.uniq(&:name).map do |bus|
          model = bus.model_resolved? ? bus.model.name : 'unresolved'
          item(bus.name, :variable, "bus #{model}", bus.doc)
        end
      end

      def libraries(_resolver, _match)
        app.orogen.available_library_names.sort.map do |name|
          loaded = app.orogen.loaded?(name) ? app.orogen.library(name) : nil
          tasks = loaded ? "Task models: #{loaded.tasks.values.map(&:name).join(', ')}" : 'not loaded yet'
          item(name, :module, 'task library', tasks)
        end
      end

      def deployments(_resolver, _match)
        app.orogen.deployment_names.map do |name|
          tasks = app.orogen.find_deployment(name).task_activities.map { |t| "#{t.name} (#{t.model.name})" }
          item(name, :module, 'deployment', tasks.join(', '))
        end
      end

      def sections(resolver, _match)
        model = resolver.conf_model(resolver.statement_above)
        ConfSections.of(app, model).map do |section|
          item(section.name, :value, "#{section.kind} of #{model.name}", section.what.join(', '))
        end
      end

      # The inputs of the children of the composition around the cursor,
      # as child_child.port_port; those of the connected output's type when
      # the line says which output it is.
      def sinks(resolver, _match)
        composition = resolver.composition
        return [] unless composition

        source = source_port(composition, resolver.cursor.before)
        composition.each_child.flat_map do |name, child|
          child.ports.values.select { |p| p.input? && (source.nil? || p.type == source.type) }
               .map { |p| item("#{name}_child.#{p.name}_port", :field, "#{p.direction} #{p.type.name}") }
        end
      end

      def source_port(composition, before)
        found = before.match(/(\w+)_child\.(\w+)_port\.connect_to\s*\(?\s*\w*\z/)
        child = found && composition.find_child(found[1])
        child&.ports&.[](found[2])
      end

      def orogen_libraries(_resolver, _match)
        app.orogen.loaded_library_names.sort.map do |name|
          item(name, :module, 'task library', app.orogen.library(name).tasks.values.map(&:name).join(', '))
        end
      end

      def orogen_tasks(_resolver, match)
        return [] unless app.orogen.loaded?(match[1])

        app.orogen.library(match[1]).tasks.values.map do |task|
          item(task.name.split('::').last, :class, 'task model', catalog.entry_for(task)&.summary)
        end
      end

      def child_ports(resolver, match)
        child = resolver.composition&.find_child(match[1])
        return [] unless child

        child.ports.values.map { |p| item("#{p.name}_port", :field, "#{p.direction} #{p.type.name}") }
      end
    end
  end
end
