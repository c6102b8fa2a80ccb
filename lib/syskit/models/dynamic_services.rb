# frozen_string_literal: true

require 'syskit/models/dynamic_data_service'

module Syskit
  module Models
    # +dynamic_service+ on task and composition models (see
    # DynamicDataService, CompositionDynamicServices).
    module DynamicServices
      # Declares a dynamic service of +model+ named +as+; the block declares
      # each instance (see DynamicDataService). Syskit's +dynamic:+,
      # +remove_when_unused:+ and +addition_requires_reconfiguration:+ say
      # when a running component is reconfigured: recorded (the old
      # +dynamic: true+ means no reconfiguration), no effect on a plan.
      def dynamic_service(model, as: nil, dynamic: nil, remove_when_unused: true,
                          addition_requires_reconfiguration: !dynamic, &block)
        location = Location.of_caller
        unless dynamic.nil?
          Compat::Roby.warn_deprecated('dynamic: of dynamic_service is deprecated, ' \
                                       "write addition_requires_reconfiguration: #{!dynamic} (#{location})")
        end
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

        Component.declarations_changed
        (@dynamic_services ||= {})[as.to_s] = DynamicDataService.new(
          self, as.to_s, model, block, location,
          addition_requires_reconfiguration: addition_requires_reconfiguration, remove_when_unused: remove_when_unused
        )
      end

      # Syskit's +require_dynamic_service+: the instance +as+ of the dynamic
      # service +dynamic_name+ (its block given +options+) becomes a service
      # of this model, with the ports it creates. As in Syskit, this
      # changes the model itself: to leave a task model as it is, ask it
      # of a specialization (+Task.specialize+, or +Task.with_dynamic_service+).
      # Asking again for an instance of the same model returns it.
      def require_dynamic_service(dynamic_name, as:, **options)
        location = Location.of_caller
        dynamic = fetch_dynamic_service(dynamic_name, location, "to require as '#{as}'")
        existing = find_service(as.to_s)
        return existing if existing&.fullfills?(dynamic.service_model)
        raise already_a_service(existing, dynamic, location) if existing

        service = instantiate_dynamic_service(dynamic, as.to_s, options, location)
        (@required_dynamic_services ||= []) << service
        service
      end

      # The dynamic service +name+, or an error located at +location+
      # saying what it was asked for (+purpose+).
      def fetch_dynamic_service(name, location, purpose)
        found = find_dynamic_service(name)
        return found if found

        known = dynamic_service_names
        hint = "its dynamic services: #{known.join(', ')}"
        hint = "declare it in #{self.name}'s extension: dynamic_service Model, as: 'name' do ... end" if known.empty?
        raise DeclarationError.new(
          "#{self.name} has no dynamic service '#{name}' #{purpose}#{Naming.did_you_mean(name.to_s, known)}",
          location: location, hint: hint
        )
      end

      # The dynamic service +name+, inherited ones included: those are
      # promoted to this model (see DynamicDataService#attach), once.
      def find_dynamic_service(name)
        name = name.to_s
        own = @dynamic_services && @dynamic_services[name]
        return own if own
        return unless superclass.respond_to?(:find_dynamic_service)

        promoted = (@promoted_dynamic_services ||= {})
        promoted[name] ||= superclass.find_dynamic_service(name)&.attach(self)
      end

      # Names of the dynamic services, inherited ones included, sorted.
      def dynamic_service_names
        inherited = superclass.respond_to?(:dynamic_service_names) ? superclass.dynamic_service_names : []
        (inherited + (@dynamic_services || {}).keys).uniq.sort
      end

      private

      # The service the block of +dynamic+ declares for the instance +as+,
      # registered on this model: on a task model, with the ports it
      # creates.
      def instantiate_dynamic_service(dynamic, as, options, location)
        service, ports = dynamic.instance_for(as, options, location, on: self)
        ports.each { |port| spec.add_port(port) }
        register_service(service)
      end

      def already_a_service(existing, dynamic, location)
        DeclarationError.new(
          "#{name} already has a service '#{existing.full_name}' (#{existing.model}), not the " \
          "#{dynamic.service_model} of dynamic service '#{dynamic.name}'",
          location: location, hint: "give the instance another name with as: 'other_name'"
        )
      end
    end
  end
end
