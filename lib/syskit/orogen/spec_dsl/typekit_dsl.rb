# frozen_string_literal: true

module Syskit
  module Orogen
    # +typekit do ... end+ and +typekit.export_types ...+ in an .orogen
    # file: how oroGen builds the project's typekit (which types it exports,
    # which libraries it links). None of it changes a plan; declaring a
    # typekit makes the project's own types (/NAME/) opaque.
    class TypekitDSL
      include StatementsDSL

      def initialize(loader)
        @loader = loader
      end

      def dsl_context
        'a typekit block'
      end

      # Build statements, accepted: only the build reads them.
      %i[export_types load opaque_type include_directories link_directories target_link_libraries
         orogen_pkg_check_modules using_library enable_namespace max_sizes type_export_policy
         smart_ptr ro_ptr_type shared_ptr remove_types ros_mappings resolve_registry_includes
         export_types_from].each do |statement|
        define_method(statement) { |*_args, **_options, &_block| self }
      end

      # The typekit's Typelib registry, which some specs (Rock's std
      # typekit) fill in Ruby: not modelled, whatever is called on it.
      def registry
        Compat::Ignored.instance
      end

      # A type of the typekit, whose build metadata some specs set
      # (+find_type('/pcl/Mesh').metadata.set('orogen_include', ...)+): only
      # the build reads it.
      def find_type(_name)
        Compat::Ignored.instance
      end
    end
  end
end
