# frozen_string_literal: true

require 'syskit/models/bound_dynamic_data_service'

module Syskit
  module Models
    # A service a task model provides under names chosen later, with ports
    # it creates for each (Syskit's +dynamic_service+): a gazebo model task
    # exports any link as a device, each on its own port.
    #
    #   Syskit.extend_model OroGen.rock_gazebo.ModelTask do
    #     dynamic_service Devices::Gazebo::Link, as: 'link_export' do
    #       driver_for Devices::Gazebo::Link, 'link_state_samples' => "#{name}_samples"
    #     end
    #   end
    #
    # The block runs once per instance (+device(...).slave('link_export',
    # as: 'camera_link')+), with the instance's +name+ and +options+. Its
    # mappings may name ports the task does not have: they are created,
    # when one of the task's dynamic_*_port patterns allows them.
    class DynamicDataService
      # The component model it is declared on, its name, the model of
      # the services it makes (+service_model+), where it is declared.
      attr_reader :component_model, :name, :service_model, :declared_at

      # +addition_requires_reconfiguration:+ and +remove_when_unused:+ say
      # what Syskit does with running components; recorded.
      def initialize(component_model, name, service_model, block, location, demoted: nil,
                     addition_requires_reconfiguration: true, remove_when_unused: true)
        @component_model = component_model
        @name = name
        @service_model = service_model
        @block = block
        @declared_at = location
        @addition_requires_reconfiguration = addition_requires_reconfiguration
        @remove_when_unused = remove_when_unused
        @demoted = demoted
      end

      def addition_requires_reconfiguration?
        @addition_requires_reconfiguration
      end

      def remove_when_unused?
        @remove_when_unused
      end

      # The dynamic service as the task model that declared it has it
      # (itself, unless it was promoted to a submodel, see #attach).
      def demoted
        @demoted || self
      end

      # This dynamic service as one of +component_model+, a submodel of
      # its task model (what +Sub.find_dynamic_service+ gives).
      def attach(component_model)
        DynamicDataService.new(
          component_model, name, service_model, @block, declared_at,
          demoted: demoted, addition_requires_reconfiguration: addition_requires_reconfiguration?,
          remove_when_unused: remove_when_unused?
        )
      end

      # Syskit's +instanciate+: the instance +name+ of this dynamic service
      # (its block given +options+) becomes a service of its component
      # model (see DynamicServices#require_dynamic_service), and is returned.
      def instanciate(name, **options)
        component_model.require_dynamic_service(self.name, as: name, **options)
      end

      # The service named +as+ (a BoundDataService of +on+, the task model or
      # a specialization of it) and the ports it needs created, not yet
      # registered on +on+; +location+ is where the instance is asked for.
      def instance_for(as, options, location, on: component_model)
        context = InstantiationContext.new(on, as, self, **options)
        evaluate(context, as)
        return [context.service, context.created_ports] if context.service

        raise InvalidDynamicServiceBlock.new(
          "the block of dynamic service '#{name}' of #{component_model.name} provides nothing for '#{as}'",
          location: declared_at || location,
          hint: "call provides #{service_model}, 'service_port' => \"\#{name}_port\" (or driver_for) in the block"
        )
      end

      # Runs the block on +context+ for the instance +as+, its errors
      # located in the block.
      def evaluate(context, as)
        context.instance_exec(&@block)
      rescue ScriptError, StandardError => e
        raise UserCode.translate(e, error_class: DeclarationError,
                                    context: "in dynamic service '#{name}' of #{component_model.name} for '#{as}'")
      end

      def to_s
        "dynamic service '#{name}' (#{service_model}) of #{component_model.name}"
      end

      # What the block of a dynamic service is evaluated on (Syskit's
      # +DynamicDataService::InstantiationContext.new(task_model, name,
      # dynamic_service, **options)+).
      class InstantiationContext
        # The instance's name and options.
        attr_reader :name, :options, :service, :created_ports

        def initialize(component_model, name, dynamic_service, **options)
          @dynamic = dynamic_service
          @name = name
          @options = options
          @component_model = component_model
          @created_ports = []
        end

        # The task model the instance is made on (Syskit's name for it in
        # these blocks).
        attr_reader :component_model

        # Provides +model+ (the dynamic service's model or one providing it)
        # as this instance, its ports mapped by +mappings+. +slave_of:+
        # names the service of the task it is a slave of, as Syskit writes
        # it (+provides Link, as: name, slave_of: 'driver'+): the instance
        # is then known as +driver.name+.
        def provides(model, mappings = {}, as: nil, slave_of: nil, **more)
          location = Location.of_caller
          check(model, as, location)
          master = master_service(slave_of, location) if slave_of
          mapper = PortMapper.new(component_model, model, mappings.merge(more), location, dynamic: true)
          @service = BoundDynamicDataService.new(component_model, name, model, mapper.map, location,
                                                 master: master, dynamic_service: @dynamic,
                                                 dynamic_service_options: options)
          @created_ports = mapper.created
          @service
        end
        alias driver_for provides

        # Declares a task argument of the model the instance is made on
        # (+argument "#{name}_frame"+), as the task model's +argument+.
        def argument(arg_name, **options)
          component_model.argument(arg_name, **options)
        end

        def explain_missing(method_name)
          ["unknown statement '#{method_name}' in dynamic service '#{@dynamic.name}'",
           'the block declares the instance with provides or driver_for (and task arguments with argument), ' \
           'from its name and options']
        end

        private

        def master_service(slave_of, location)
          full_name = slave_of.respond_to?(:full_name) ? slave_of.full_name : slave_of.to_s
          found = component_model.find_service(full_name)
          return found if found

          known = component_model.services.keys.sort
          raise DeclarationError.new(
            "slave_of: '#{full_name}' in dynamic service '#{@dynamic.name}' names no service of " \
            "#{component_model.name}#{Naming.did_you_mean(full_name, known)}",
            location: location, hint: known.empty? ? 'leave slave_of: out' : "its services: #{known.join(', ')}"
          )
        end

        def check(model, as, location)
          if @service
            raise DeclarationError.new("dynamic service '#{@dynamic.name}' provides twice for '#{name}'",
                                       location: location, hint: 'call provides (or driver_for) once')
          end
          if as && as.to_s != name
            raise DeclarationError.new("as: '#{as}' in dynamic service '#{@dynamic.name}': the instance is '#{name}'",
                                       location: location, hint: 'leave as: out, the name is the instance\'s')
          end
          return if model.is_a?(DataServiceModel) && model.fullfills?(@dynamic.service_model)

          raise DeclarationError.new(
            "dynamic service '#{@dynamic.name}' is a #{@dynamic.service_model}, the block provides #{model.inspect}",
            location: location, hint: "provide #{@dynamic.service_model} or a model that provides it"
          )
        end
      end
    end
  end
end
