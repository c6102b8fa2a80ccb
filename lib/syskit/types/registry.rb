# frozen_string_literal: true

require 'syskit/types/type'
require 'syskit/types/struct_type'
require 'syskit/namespace'

module Syskit
  module Types
    # All the types an app knows of, by canonical name, plus the +Types+
    # namespace object that exposes them to Ruby code.
    class Registry
      # Spellings oroGen accepts for its base types, and their canonical name.
      ALIASES = {
        'char' => '/int8_t', 'short' => '/int16_t', 'int' => '/int32_t', 'long' => '/int64_t',
        'long long' => '/int64_t', 'unsigned char' => '/uint8_t', 'unsigned short' => '/uint16_t',
        'unsigned int' => '/uint32_t', 'unsigned' => '/uint32_t', 'unsigned long' => '/uint64_t',
        'unsigned long long' => '/uint64_t', 'double' => '/double', 'float' => '/float',
        'bool' => '/bool', 'string' => '/std/string', '/string' => '/std/string'
      }.freeze

      # The template of oroGen's ro_ptr(type).
      RO_PTR = '/RTT/extras/ReadOnlyPointer'

      # Typekits whose types are built in (no file to load).
      BUILTIN_TYPEKITS = %w[std].freeze

      attr_reader :namespace

      def initialize
        @types = {}
        @namespace = Syskit::Namespace.new('Types')
        @opaque_namespaces = {}
        register_builtins
      end

      # The canonical spelling of a type name: leading slash, base type
      # aliases resolved, container arguments normalized.
      #
      # Kept per name: a port created at configure time (a bus driver's
      # port for each device) asks for its type's name each time.
      def self.normalize(name)
        NORMALIZED[name] || (NORMALIZED[name] = canonical(name).freeze)
      end

      NORMALIZED = {} # rubocop:disable Style/MutableConstant -- filled as names are met

      def self.canonical(name)
        name = name.to_s.strip
        return "#{normalize(Regexp.last_match(1))}[#{Regexp.last_match(2)}]" if name =~ /\A(.+)\[(\d+)\]\z/

        # A template whose '>' is missing: oroGen accepts it.
        name = "#{name}#{'>' * (name.count('<') - name.count('>'))}" if name.count('<') > name.count('>')
        if (m = name.match(/\A(.*?)<(.+)>\z/))
          return "#{normalize(m[1])}<#{normalize(m[2])}>"
        end

        # C++ spellings: base::samples::RigidBodyState is /base/samples/RigidBodyState.
        name = name.gsub('::', '/')
        ALIASES.fetch(name) { ALIASES.fetch(name.delete_prefix('/')) { name.start_with?('/') ? name : "/#{name}" } }
      end
      private_class_method :canonical

      # The type called +name+, nil if it is not known. Containers and arrays
      # of known types are created on demand.
      def find(name)
        return name if name.is_a?(Type)

        canonical = Registry.normalize(name)
        @types[canonical] || derive(canonical)
      end

      # Like {#find}, but raises a located Syskit::TypeError for unknown names.
      # The rule: a type is known when it is a base type, described by a
      # typekit, or in the namespace of a typekit without a description (it
      # is then opaque; see #opaque_typekit); +opaque_ok+ (an .orogen file
      # that imports a C/C++ header) accepts any other as opaque.
      def resolve(name, location: nil, opaque_ok: false)
        found = find(name) || (find(name) if describe(name))
        return found if found

        canonical = Registry.normalize(name)
        return register(OpaqueType.new(canonical)) if opaque_ok || opaque_namespace?(canonical)
        return register(OpaqueType.new(canonical)) if @voucher&.call(canonical, location)

        raise unknown_type_error(canonical, location)
      end

      # How a typekit description is found and imported when one of its
      # types is named before the typekit was imported (see TypekitSearch):
      # a block given the typekit's name, true when it imported one.
      attr_writer :describer

      # Whether a type of no known namespace is accepted as opaque all the
      # same (see TypekitSearch#vouch): a block given its name and where
      # it is named.
      attr_writer :voucher

      # Registers +type+ under its name, or under +name+ for a typedef.
      def register(type, name = type.name)
        @types[name] = type
        segments = name.delete_prefix('/').split('/')
        @namespace.add(segments, type) if segments.size > 1 && name.match?(%r{\A[/\w]+\z})
        type
      end

      # Declares that types under /+name+/ come from a typekit the gem cannot
      # read: any type in that namespace is accepted as opaque.
      def opaque_typekit(name)
        @opaque_namespaces[name] = true
      end

      def opaque_namespace?(canonical)
        @opaque_namespaces.key?(canonical.delete_prefix('/').split('/').first)
      end

      def each_type(&)
        @types.each_value(&)
      end

      def names
        @types.keys.sort
      end

      private

      # Imports the description of the typekit +name+'s first segment
      # names, if there is one not imported yet.
      def describe(name)
        namespace = Registry.normalize(name).delete_prefix('/').split(%r{[/<]}).first
        @describer&.call(namespace)
      end

      # A known type, or an opaque one of a namespace whose typekit has no
      # description: what containers and arrays may hold, whatever the
      # order types are first named in.
      def find_element(name)
        find(name) || (find(name) if describe(name)) || (register(OpaqueType.new(name)) if opaque_namespace?(name))
      end

      def derive(canonical)
        if (m = canonical.match(/\A(.+)\[(\d+)\]\z/))
          element = find_element(m[1])
          register(ArrayType.new(canonical, element, Integer(m[2]))) if element
        elsif (m = canonical.match(/\A(.*?)<(.+)>\z/))
          element = find_element(m[2])
          return unless element

          if m[1] == '/std/vector' then register(ContainerType.new(canonical, element))
          elsif m[1] == RO_PTR then register(OpaqueType.new(canonical))
          end
        end
      end

      def unknown_type_error(canonical, location)
        TypeError.new(
          "unknown type #{canonical}#{Naming.did_you_mean(canonical, @types.keys)}",
          location: location,
          hint: "import the typekit that defines it (import_types_from 'typekit_name'); " \
                'an app declares its own types in models/typekits/NAME.rb'
        )
      end

      def register_builtins
        { 8 => 'int8_t', 16 => 'int16_t', 32 => 'int32_t', 64 => 'int64_t' }.each do |bits, n|
          register(IntegerType.new("/#{n}", bits: bits, signed: true))
          register(IntegerType.new("/u#{n}", bits: bits, signed: false))
        end
        register(FloatType.new('/double'))
        register(FloatType.new('/float'))
        register(BoolType.new('/bool'))
        register(StringType.new('/std/string'))
      end
    end
  end
end
