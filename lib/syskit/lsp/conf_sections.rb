# frozen_string_literal: true

module Syskit
  module LSP
    # The names with_conf can take for a model, with where each is
    # declared: a task model's sections of config/orogen/<lib>::<Task>.yml
    # (the app's over its bundles', as App#conf_file merges them), a
    # composition's named configurations (+conf 'summer', ...+).
    module ConfSections
      # +kind+: 'section' (of a file) or 'configuration' (of a
      # composition); +what+: the settings a section sets, or the sections
      # a configuration gives each child ('monitor: default, summer').
      Section = Struct.new(:kind, :name, :location, :what)

      # The sections of +model+, in declaration order; none when it has no
      # configuration, or when its file cannot be read (that is a
      # diagnostic of its own).
      def self.of(app, model)
        return [] unless model
        return of_composition(model) if model.is_a?(Class) && model <= Composition

        file = app.conf_file(model)
        return [] unless file

        file.sections.values.map do |s|
          Section.new('section', s.name, Location.new(s.path, [s.line, 1].max), s.settings.keys)
        end
      rescue Syskit::Error
        []
      end

      def self.find(app, model, name)
        of(app, model).find { |s| s.name == name }
      end

      def self.of_composition(model)
        model.configurations.map do |name, children|
          what = children.map { |child, sections| "#{child}: #{sections.join(', ')}" }
          Section.new('configuration', name, model.configuration_location(name), what)
        end
      end
    end
  end
end
