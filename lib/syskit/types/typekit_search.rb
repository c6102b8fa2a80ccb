# frozen_string_literal: true

module Syskit
  module Types
    # How +import_types_from NAME+ finds a typekit: built in (+std+), a Ruby
    # description (NAME.rb in the search directories), a C/C++ header, or,
    # in .orogen files, a typekit the gem has no description of, whose
    # types are then accepted as opaque.
    class TypekitSearch
      HEADER = /\.(h|hh|hpp|hxx)\z/i

      attr_reader :dirs

      # +dirs+: directories searched for NAME.rb, in order.
      def initialize(registry, dirs)
        @registry = registry
        @dirs = dirs
        @imported = {}
      end

      # Imports typekit +name+ once. Returns :typekit when its types are
      # known, :header for C/C++ headers and :opaque for a typekit without
      # a description (accepted only with +from_spec+).
      def import(name, location:, from_spec: false)
        return :header if name.match?(HEADER)
        return @imported[name] if @imported.key?(name)
        return @imported[name] = :typekit if Registry::BUILTIN_TYPEKITS.include?(name)

        path = find(name)
        if path
          @imported[name] = :typekit
          importer = ->(typekit, at) { import(typekit, location: at) }
          TypekitLoader.new(@registry, name, importer).load(path)
        elsif from_spec
          @registry.opaque_typekit(name)
          @imported[name] = :opaque
        else
          raise FileLoadError.new("no typekit '#{name}'",
                                  location: location, hint: "declare its types in models/typekits/#{name}.rb")
        end
      end

      # The description of typekit +name+, nil when there is none.
      def find(name)
        dirs.map { |d| File.join(d, "#{name}.rb") }.find { |p| File.file?(p) }
      end
    end
  end
end
