# frozen_string_literal: true

require 'syskit/doc/catalog'
require 'syskit/lsp/target'

module Syskit
  module LSP
    # Where what is under the cursor was declared, from the locations the
    # models, devices, definitions, task libraries and configuration files
    # recorded when the app was loaded: a model constant to its
    # declaration, a task library or OroGen.lib.Task to its .orogen file, a
    # section of with_conf to its header in config/orogen/*.yml, a device
    # or bus name (through 'can0', gps_dev) to its device statement, a
    # port (+follower_child.pose_port+) to its declaration.
    #
    # Locations are Syskit::Location, with 1-based lines (line 1 for a
    # file as a whole).
    class Definition
      attr_reader :app

      def initialize(app)
        @app = app
      end

      # The declarations of what is at +line+/+character+ (0-based) of
      # the buffer +text+ of +path+; empty when there is none.
      def at(path, text, line, character)
        resolver = Resolver.new(app, Cursor.new(path, text, line, character))
        return all_sections(resolver) if resolver.cursor.identifier == 'with_conf'

        target = resolver.target
        target ? locations(target) : []
      end

      private

      def locations(target)
        location =
          case target.kind
          when :model then model_location(target.object)
          when :task_library then Location.new(target.object.path, 1)
          when :device, :definition, :port, :deployment then target.object.declared_at
          when :conf then section_location(target.object, target.name)
          end
        [whole_file(location)].compact
      end

      def model_location(model)
        return model.spec.declared_at if model.respond_to?(:spec) && model.spec

        model.declared_at if model.respond_to?(:declared_at)
      end

      def section_location(model, name)
        ConfSections.find(app, model, name)&.location
      end

      # The sections a with_conf call names, when the cursor is on
      # with_conf itself.
      def all_sections(resolver)
        cursor = resolver.cursor
        names = cursor.tokens.drop(cursor.index + 1).select { |t| t.type == :on_tstring_content }.map(&:text)
        model = resolver.conf_model(resolver.statement_above)
        names.filter_map { |n| section_location(model, n) }
      end

      def whole_file(location)
        return unless location&.path

        location.lineno.to_i.positive? ? location : Location.new(location.path, 1)
      end
    end
  end
end
