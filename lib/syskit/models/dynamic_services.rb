# frozen_string_literal: true

require 'syskit/models/dynamic_service'

module Syskit
  module Models
    # +dynamic_service+ on task models (see DynamicService).
    module DynamicServices
      # Declares a dynamic service of +model+ named +as+; the block declares
      # each instance (see DynamicService). Syskit's +dynamic:+,
      # +remove_when_unused:+ and +addition_requires_reconfiguration:+ say
      # when a running component is reconfigured: accepted, no effect on a
      # plan.
      def dynamic_service(model, as: nil, dynamic: false, remove_when_unused: true, # rubocop:disable Lint/UnusedMethodArgument
                          addition_requires_reconfiguration: true, &block) # rubocop:disable Lint/UnusedMethodArgument
        location = Location.of_caller
        unless model.is_a?(DataServiceModel) && as && block
          raise DeclarationError.new(
            'dynamic_service expects a service model, a name and a block',
            location: location,
            hint: "write dynamic_service Model, as: 'name' do provides Model, 'port' => \"\#{name}_port\" end"
          )
        end
        if find_dynamic_service(as)
          raise DeclarationError.new("#{name} already has a dynamic service named '#{as}'",
                                     location: location, hint: "give this one another name with as: 'other_name'")
        end

        ComponentModel.declarations_changed
        (@dynamic_services ||= {})[as.to_s] = DynamicService.new(self, as.to_s, model, block, location)
      end

      # The dynamic service +name+, inherited ones included.
      def find_dynamic_service(name)
        own = @dynamic_services && @dynamic_services[name.to_s]
        own || (superclass.find_dynamic_service(name) if superclass.respond_to?(:find_dynamic_service))
      end

      # Names of the dynamic services, inherited ones included, sorted.
      def dynamic_service_names
        inherited = superclass.respond_to?(:dynamic_service_names) ? superclass.dynamic_service_names : []
        (inherited + (@dynamic_services || {}).keys).uniq.sort
      end
    end
  end
end
