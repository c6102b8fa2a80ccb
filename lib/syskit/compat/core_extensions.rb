# frozen_string_literal: true

module Syskit
  module Compat
    # Methods of Rock's utilrb that bundles call on their modules. Included
    # in Module once syskit is loaded, as utilrb does in Rock.
    module CoreExtensions
      # +Services.const_defined_here?('Pose')+: a constant of this module
      # itself, not inherited.
      def const_defined_here?(name)
        const_defined?(name, false)
      end

      private

      # Roby's +backward_compatible_constant :OldName, 'New::Name', 'file'+:
      # the old name of a model that moved.
      def backward_compatible_constant(old_name, new_name, file)
        require file
        const_set(old_name, Object.const_get(new_name)) unless const_defined?(old_name, false)
      end

      # utilrb's +attr_predicate :enabled, true+: +enabled?+ (and +enabled=+).
      def attr_predicate(name, writable = false) # rubocop:disable Style/OptionalBooleanParameter -- utilrb's
        name = name.to_s.delete_suffix('?')
        ivar = :"@#{name}"
        define_method(:"#{name}?") { instance_variable_get(ivar) ? true : false }
        attr_writer name if writable
      end

      # +attribute(:providers) { {} }+: a reader whose value is the block's
      # result the first time it is read, and a writer.
      def attribute(name, &default)
        ivar = :"@#{name}"
        define_method(name) do
          instance_variable_defined?(ivar) ? instance_variable_get(ivar) : instance_variable_set(ivar, default&.call)
        end
        attr_writer name
      end
    end

    # utilrb's (and facets') string case conversions, which Rock model
    # code calls to make names (+"open_loop_#{name.snakecase}"+).
    module StringExtensions
      def snakecase
        Naming.underscore(self)
      end

      def camelcase
        split('_').map { |part| part[0] ? part[0].upcase + part[1..] : part }.join
      end
    end
  end
end

Module.include(Syskit::Compat::CoreExtensions)
String.include(Syskit::Compat::StringExtensions)
