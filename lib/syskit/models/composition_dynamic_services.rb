# frozen_string_literal: true

require 'syskit/models/dynamic_services'

module Syskit
  module Models
    # Dynamic services of composition models, as in Syskit: the block of
    # each instance (+require_dynamic_service 'x', as: 'name'+) changes the
    # composition model itself, adding, overloading and exporting children
    # and providing the service on what it exported. Part of Composition.
    module CompositionDynamicServices
      include DynamicServices

      # What the block of a composition's dynamic service is evaluated on:
      # the instance's +name+ and +options+, +provides+, and the
      # composition's statements and child readers.
      class Context
        STATEMENTS = %i[add add_optional add_main overload export connect conf argument].freeze

        attr_reader :composition_model, :name, :options

        def initialize(composition_model, name, options)
          @composition_model = composition_model
          @name = name
          @options = options
          define_child_readers
        end

        STATEMENTS.each do |statement|
          define_method(statement) do |*args, **kw, &block|
            result = composition_model.public_send(statement, *args, **kw, &block)
            define_child_readers
            result
          end
        end

        def provides(model, mappings = {}, as: nil, **more)
          composition_model.provides(model, mappings, as: as, **more)
        end

        private

        def define_child_readers
          composition_model.child_names.each do |child|
            reader = "#{child}_child"
            define_singleton_method(reader) { composition_model.find_child(child) } unless respond_to?(reader)
          end
        end
      end

      private

      def instantiate_dynamic_service(dynamic, as, options, location)
        dynamic.evaluate(Context.new(self, as, options), as)
        service = find_service(as)
        return service if service&.fullfills?(dynamic.service_model)

        raise DeclarationError.new(
          "the block of dynamic service '#{dynamic.name}' of #{self} provides no #{dynamic.service_model} as '#{as}'",
          location: dynamic.declared_at || location,
          hint: "call provides #{dynamic.service_model}, as: name in the block"
        )
      end
    end
  end
end
