# frozen_string_literal: true

module Syskit
  module Types
    # How +import_types_from NAME+ finds a typekit: built in (+std+), a Ruby
    # description (NAME.rb in the search directories), a C/C++ header, or a
    # typekit the gem has no description of, whose types (those under
    # /NAME/) are then accepted as opaque.
    class TypekitSearch
      HEADER = /\.(h|hh|hpp|hxx)\z/i

      attr_reader :dirs

      # +dirs+: directories searched for NAME.rb, in order.
      def initialize(registry, dirs)
        @registry = registry
        @dirs = dirs
        @imported = {}
        @opaque = {}
        @vouched = {}
        registry.describer = ->(name) { describe(name) }
        registry.voucher = ->(type_name, location) { vouch(type_name, location) }
      end

      # Whether a typekit imported without a description may define
      # +type_name+, of another namespace: real typekits define types outside
      # their own (auv_control's /base/LinearAngular6DPIDSettings). True,
      # with one warning per namespace, when some undescribed typekit is
      # imported and no description covers the type's namespace.
      def vouch(type_name, location)
        namespace = type_name.delete_prefix('/').split(%r{[/<]}).first
        return false if @opaque.empty? || Registry::BUILTIN_TYPEKITS.include?(namespace) || find(namespace)
        return true if @vouched.key?(namespace)

        @vouched[namespace] = location
        Syskit.app&.problems&.push(Warning.new(
          "#{type_name} is taken as opaque: no typekit describes /#{namespace}/, and #{vouchers} " \
          'imported without a description, may define it',
          location: location,
          hint: "describe it in models/typekits/#{namespace}.rb, or import the typekit that defines it"
        ))
        true
      end

      # Imports the description of typekit +name+ when there is one that is
      # not imported yet: a type of a described typekit is known wherever
      # it is named, whatever was imported before. True when it imported.
      def describe(name)
        return false if name.nil? || @imported.key?(name) || !(path = find(name))

        import(name, location: Location.new(path, 1))
        true
      end

      # Imports typekit +name+ once. Returns :typekit when its types are
      # described, :header for a C/C++ header and :opaque for a typekit
      # without a description.
      def import(name, location:)
        return :header if name.match?(HEADER)
        return @imported[name] if @imported.key?(name)
        return @imported[name] = :typekit if Registry::BUILTIN_TYPEKITS.include?(name)

        path = find(name)
        if path
          @imported[name] = :typekit
          importer = ->(typekit, at) { import(typekit, location: at) }
          TypekitLoader.new(@registry, name, importer).load(path)
        else
          @registry.opaque_typekit(name)
          @opaque[name] = location
          @imported[name] = :opaque
        end
      end

      # Typekits imported without a description, and where each was first
      # imported.
      attr_reader :opaque

      # The undescribed typekits, as a message names them.
      def vouchers
        names = @opaque.keys.sort
        names.size == 1 ? "the typekit #{names.first}," : "the typekits #{names.join(', ')},"
      end

      # The description of typekit +name+, nil when there is none.
      def find(name)
        dirs.map { |d| File.join(d, "#{name}.rb") }.find { |p| File.file?(p) }
      end
    end
  end
end
