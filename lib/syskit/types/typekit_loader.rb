# frozen_string_literal: true

module Syskit
  module Types
    # Evaluates a typekit file (models/typekits/NAME.rb), where an app
    # declares in Ruby the types its configure code builds:
    #
    #   struct 'Device' do
    #     field 'name', '/std/string'
    #     field 'id', '/uint32_t'
    #   end
    #   enum 'Mode', %w[ACTIVE PASSIVE]
    #   opaque 'Statistics'   # defined in a C++ header, kept as plain data
    #
    # Names are relative to the typekit ('Device' is /NAME/Device).
    class TypekitLoader
      # The statements of a typekit file.
      class DSL
        def initialize(loader)
          @loader = loader
        end

        def struct(name, &block)
          fields = FieldsDSL.new(@loader)
          fields.instance_eval(&block) if block
          @loader.define(name) { |full| StructType.new(full, fields.fields) }
        end

        def enum(name, values)
          @loader.define(name) { |full| EnumType.new(full, values) }
        end

        def opaque(name)
          @loader.define(name) { |full| OpaqueType.new(full) }
        end

        # A typedef: +alias_type 'commands/Joints', 'samples/Joints'+ makes
        # /NAME/commands/Joints the very type /NAME/samples/Joints is.
        def alias_type(name, existing)
          @loader.alias(name, existing)
        end

        def import_types_from(name)
          @loader.import(name)
        end

        # Types of this typekit's namespace that the file does not describe
        # are accepted as opaque (for typekits described in part).
        def accept_unknown_types
          @loader.registry.opaque_typekit(@loader.name)
        end

        def explain_missing(name)
          statements = %w[struct enum opaque alias_type import_types_from accept_unknown_types]
          ["unknown statement '#{name}' in a typekit file#{Naming.did_you_mean(name, statements)}",
           "typekit files declare #{statements.join(', ')}"]
        end
      end

      # The statements of a struct block.
      class FieldsDSL
        attr_reader :fields

        def initialize(loader)
          @loader = loader
          @fields = {}
        end

        def field(name, type)
          location = Location.of_caller
          if @fields.key?(name.to_s)
            raise TypeError.new("field '#{name}' is declared twice",
                                location: location, hint: 'give each field its own name')
          end

          @fields[name.to_s] = @loader.registry.resolve(type, location: location)
        end
      end

      attr_reader :registry, :name

      def initialize(registry, name, importer)
        @registry = registry
        @name = name
        @importer = importer
      end

      def load(path)
        UserCode.evaluate(path, DSL.new(self), error_class: TypeError)
      end

      def define(relative)
        full = full_name(relative)
        if registry.find(full)
          raise TypeError.new("type #{full} is already defined",
                              location: Location.of_caller, hint: 'remove the second definition')
        end

        registry.register(yield(full), full)
      end

      def alias(relative, existing)
        target = registry.resolve(full_name(existing), location: Location.of_caller)
        define(relative) { target }
      end

      def full_name(relative)
        relative.start_with?('/') ? relative : "/#{name}/#{relative}"
      end

      def import(name)
        @importer.call(name, Location.of_caller)
      end
    end
  end
end
