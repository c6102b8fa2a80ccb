# frozen_string_literal: true

module Syskit
  module Models
    module Placeholder
      # How placeholder models are made, as Syskit's Placeholder::Creation:
      # Placeholder extends it, and so does each kind of placeholder made
      # by #new_specialized_placeholder (whose models extend that kind).
      module Creation
        # The placeholder model of +models+ (service models, with at most
        # one component model or service of one), made once per component
        # model and set of services: the component model (or service)
        # itself when it provides them all, a service of the placeholder
        # when a service was given.
        def for(models, component_model: nil, as: nil)
          task_model, services, srv = resolve_models_argument(models, component_model: component_model)
          return srv || task_model if services.empty?

          key = [self, services.to_set]
          model = (task_model.placeholder_models[key] ||=
                     create_for(services, component_model: task_model, as: as))
          srv ? srv.attach(model) : model
        end

        # A new placeholder model of this kind for +models+ (see #for),
        # named +as+ or after what it stands for. It provides its services
        # as +m0+, +m1+...
        def create_for(models, component_model: nil, as: nil)
          task_model, services, = resolve_models_argument(models, component_model: component_model)
          builder = PlaceholderBuilder.new(task_model, services)
          model = builder.build
          model.extend(self)
          model.include(@task_extension) if @task_extension
          model.instance_variable_set(:@proxied_component_model, task_model)
          model.instance_variable_set(:@proxied_data_service_models, services.dup.freeze)
          model.instance_variable_set(:@placeholder_name, as || default_name(task_model, services))
          services.each_with_index { |srv, i| model.provides(srv, builder.mappings[i], as: "m#{i}") }
          model
        end

        # +[component model, service models it does not provide yet, the
        # service given as component, or nil]+ for the arguments of #for.
        def resolve_models_argument(models, component_model: nil)
          models = models.to_a
          bases = models.select { |m| m.is_a?(Class) || m.is_a?(BoundDataService) }
          bases << component_model if component_model
          if bases.size > 1
            raise DeclarationError.new(
              "a placeholder derives from one component model at most, got #{bases.join(', ')}",
              location: Location.of_caller, hint: 'give one component model (or service) and service models'
            )
          end

          base = bases.first || Syskit::Component
          srv = base if base.is_a?(BoundDataService)
          task_model = srv ? srv.component_model : base
          services = models.grep(DataServiceModel).uniq.reject { |m| task_model.fullfills?(m) }
          [task_model, services, srv]
        end

        # A kind of placeholder of its own (its own cache of models): the
        # block adds methods to its models, +task_extension+ to their tasks.
        def new_specialized_placeholder(task_extension: nil, &block)
          kind = Module.new
          kind.include(Placeholder)
          kind.extend(Creation)
          kind.instance_variable_set(:@task_extension, task_extension)
          kind.module_eval(&block) if block
          kind
        end

        private

        def default_name(task_model, services)
          names = services.map(&:to_s)
          names.unshift(task_model.to_s) unless task_model.equal?(Syskit::Component)
          "Syskit::Models::Placeholder<#{names.join(',')}>"
        end
      end

      # Builds the task model of a placeholder: a submodel of its component
      # model (of a task context for services alone) with the ports of its
      # services that the component does not have, abstract.
      class PlaceholderBuilder
        # The port mappings of each service, in order (see .service_ports).
        attr_reader :mappings

        def initialize(task_model, services)
          @task_model = task_model
          @services = services
        end

        # The ports a task needs to provide each of +services+ (by name),
        # and each service's port mappings: a port whose name another
        # service or the +base+ model took with another type or direction
        # gets a name of its own (+pose_srv1+).
        def self.service_ports(services, base = nil)
          ports = {}
          mappings = services.each_with_index.map do |srv, index|
            srv.ports.each_value.to_h do |p|
              taken = ports[p.name] || base&.find_port(p.name)
              clash = taken && (taken.type != p.type || taken.direction != p.direction)
              name = clash ? "#{p.name}_srv#{index}" : p.name
              ports[name] ||= Syskit::Orogen::Port.new(name, p.direction, p.type)
              [p.name, name]
            end
          end
          [ports, mappings]
        end

        def build
          base = @task_model.equal?(Syskit::Component) ? Syskit::TaskContext : @task_model
          spec = Orogen::TaskSpec.new('placeholder', nil)
          spec.superclass = base.spec if base.respond_to?(:spec) && base.spec
          ports, @mappings = PlaceholderBuilder.service_ports(@services, base)
          ports.each_value { |p| spec.ports[p.name] = p unless base.find_port(p.name) }
          spec.abstract = true
          spec.finalize
          model = base.new_model(spec)
          model.include(Syskit::Placeholder)
          model
        end
      end
    end
  end
end
