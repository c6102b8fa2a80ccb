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
        STATEMENTS = %w[struct enum opaque alias_type import_types_from accept_unknown_types specialize_model
                        convert_from_ruby ruby_library].freeze
        # A type name, relative to the typekit (Device) or absolute (/my_bus/Device).
        TYPE_NAME = %r{\A/?[A-Za-z_]\w*(?:/[A-Za-z_]\w*)*\z}

        def initialize(loader)
          @loader = loader
        end

        def close
          @loader = nil
        end

        def struct(name = nil, &block)
          name = type_name(name, 'struct', "struct 'Device' do field 'id', '/uint32_t' end")
          Arguments.block(block, statement: "struct '#{name}'", error_class: TypeError,
                                 example: "struct '#{name}' do field 'id', '/uint32_t' end")
          fields = FieldsDSL.new(@loader)
          fields.instance_eval(&block)
          @loader.define(name) { |full| StructType.new(full, fields.fields) }
        end

        def enum(name = nil, values = nil)
          name = type_name(name, 'enum', "enum 'Mode', %w[ACTIVE PASSIVE]")
          values = Arguments.names(values, statement: "enum '#{name}'", what: 'value names', error_class: TypeError,
                                           example: "enum '#{name}', %w[ACTIVE PASSIVE]")
          @loader.define(name) { |full| EnumType.new(full, values) }
        end

        def opaque(name = nil)
          name = type_name(name, 'opaque', "opaque 'Statistics'")
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

        # Methods of a type itself, as Typelib's +specialize_model+ gives
        # them (Rock's +Types.base.JointState.Speed(2.0)+): the block's
        # +def+s become methods of the type, which may call +new+.
        def specialize_model(name = nil, &block)
          name = type_name(name, 'specialize_model', "specialize_model 'JointState' do def Speed(v) ... end end")
          Arguments.block(block, statement: "specialize_model '#{name}'", error_class: TypeError,
                                 example: "specialize_model '#{name}' do def Speed(v) new(speed: v) end end")
          type = @loader.registry.resolve(@loader.full_name(name), location: Location.of_caller)
          type.singleton_class.class_eval(&block)
          type
        end

        # How a value of a Ruby class stands for a value of the type, as
        # Typelib's +convert_from_ruby+ (Rock writes a ::Time where a
        # /base/Time is expected): the block, evaluated on the type, makes
        # the type's value from the Ruby one.
        #
        #   convert_from_ruby ::Time, 'Time' do |time|
        #     new(microseconds: (time.to_r * 1_000_000).to_i)
        #   end
        def convert_from_ruby(ruby_class, name = nil, &block)
          example = "convert_from_ruby ::Time, 'Time' do |time| new(...) end"
          name = type_name(name, 'convert_from_ruby', example)
          Arguments.block(block, statement: "convert_from_ruby #{ruby_class}, '#{name}'", error_class: TypeError,
                                 example: example)
          location = Location.of_caller
          unless ruby_class.is_a?(Module)
            raise TypeError.new("convert_from_ruby expects a Ruby class, got #{ruby_class.inspect}",
                                location: location, hint: example)
          end
          type = @loader.registry.resolve(@loader.full_name(name), location: location)
          unless type.is_a?(StructType)
            raise TypeError.new("convert_from_ruby applies to struct types; #{type.name} is not one",
                                location: location, hint: "describe it with struct '#{name}' do ... end first")
          end
          type.convert_from_ruby(ruby_class, block)
        end

        # A Ruby library that Rock loads with this typekit's Ruby plugin,
        # and that the gem provides (+ruby_library 'base/float'+: the
        # top-level +Base.unknown+ that Rock code writes).
        def ruby_library(name)
          location = Location.of_caller
          unless Compat.provided_library?(name)
            raise TypeError.new("ruby_library '#{name}' is not a library the gem provides",
                                location: location, hint: 'remove it')
          end

          Compat.require_provided(name)
        end

        def explain_missing(name)
          ["unknown statement '#{name}' in a typekit file#{Naming.did_you_mean(name, STATEMENTS)}",
           "typekit files declare #{STATEMENTS.join(', ')}"]
        end

        private

        def type_name(name, statement, example)
          Arguments.name(name, statement: statement, what: 'a type name', pattern: TYPE_NAME, example: example,
                               error_class: TypeError)
        end
      end

      # The statements of a struct block.
      class FieldsDSL
        attr_reader :fields

        def initialize(loader)
          @loader = loader
          @fields = {}
        end

        # +unknown: true+: the field may be NaN, Rock's "unknown" for a
        # floating-point value (base::unknown), which it is when not set;
        # plans show it as null.
        def field(name = nil, type = nil, unknown: false)
          location = Location.of_caller
          name = Arguments.name(name, statement: 'field', what: 'a field name', example: "field 'id', '/uint32_t'",
                                      error_class: TypeError)
          if @fields.key?(name)
            raise TypeError.new("field '#{name}' is declared twice",
                                location: location, hint: 'give each field its own name')
          end

          type = Arguments.given(type, statement: "field '#{name}'", what: 'a type', error_class: TypeError,
                                       example: "field '#{name}', '/uint32_t'")
          resolved = @loader.registry.resolve(type, location: location)
          @fields[name] = unknown ? unknown_field(name, resolved, location) : resolved
        end

        private

        def unknown_field(name, type, location)
          return MaybeUnknownFloat.new(type.name) if type.is_a?(FloatType)

          raise TypeError.new("field '#{name}': unknown: true is for floating-point fields, #{type} is not one",
                              location: location, hint: "leave unknown: out, or make the field '/double'")
        end
      end

      attr_reader :registry, :name

      def initialize(registry, name, importer)
        @registry = registry
        @name = name
        @importer = importer
      end

      # The DSL forgets this loader once the file is read: the blocks of
      # the file live on in the methods it gives types (specialize_model's
      # define_method), and through the DSL they would keep the registry,
      # with all its types, for as long as Ruby keeps those methods (its
      # method caches outlive an unloaded app).
      def load(path)
        dsl = DSL.new(self)
        UserCode.evaluate(path, dsl, error_class: TypeError)
      ensure
        dsl&.close
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
