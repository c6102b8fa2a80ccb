# frozen_string_literal: true

module Syskit
  module Network
    # Models made up for stubs (tests' syskit_stub_* helpers, and the
    # abstract children of networks generated for tests): device models,
    # driver task models, and task models providing services.
    module StubModels
      module_function

      def device_model(base)
        base.new_submodel(name: "stub #{base.name || 'device'}")
      end

      # A driver for +model+, with the ports of the model.
      def device_driver(model)
        ports = model.ports.values.map { |p| Syskit::Orogen::Port.new(p.name, p.direction, p.type) }
        task_model("stub_driver_for_#{model_slug(model)}", ports: ports) do |task|
          task.driver_for(model, as: 'dev0')
        end
      end

      # A demultiplexing bus driver: per-device dynamic ports for both directions.
      def bus_driver(bus_model)
        type = bus_model.message_type
        task_model("stub_bus_driver_for_#{model_slug(bus_model)}", dynamic: bus_ports(type)) do |task|
          task.driver_for(bus_model, as: 'bus')
        end
      end

      # A driver for +model+ with the client ports of +bus_model+. When
      # +model+ is a bus itself, the driver also serves the devices attached
      # to it, through per-device ports of its own message type.
      def client_driver(model, bus_model, bus_to_client:, client_to_bus:)
        type = bus_model.message_type
        ports = []
        ports << Syskit::Orogen::Port.new('from_bus', :input, type) if bus_to_client
        ports << Syskit::Orogen::Port.new('to_bus', :output, type) if client_to_bus
        dynamic = model.is_a?(Models::ComBusModel) ? bus_ports(model.message_type) : []
        task_model("stub_driver_for_#{model_slug(model)}", ports: ports, dynamic: dynamic) do |task|
          task.driver_for(model, as: model.is_a?(Models::ComBusModel) ? 'bus' : 'dev')
        end
      end

      # Whether +task_model+ has the ports of a client of +bus_model+ in the
      # directions asked.
      def bus_client?(task_model, bus_model, bus_to_client:, client_to_bus:)
        type = bus_model.message_type
        ports = task_model.ports.values.select { |p| p.type == type }
        (!bus_to_client || ports.any?(&:input?)) && (!client_to_bus || ports.any?(&:output?))
      end

      # A submodel of +task_model+ that drives +model+ (a test's stub
      # device, for a task that declares no driver_for yet).
      def described_driver(task_model, model)
        task_model("#{task_model.name.gsub('::', '_')}_driving_#{model_slug(model)}", base: task_model) do |task|
          task.driver_for(model, as: 'dev')
        end
      end

      # A task model providing each of +service_models+, with their ports
      # (made once per list of services); a submodel of +base+ (a task
      # model) when given.
      def service_provider(service_models, base: nil)
        @service_providers ||= {}
        @service_providers[[service_models, base]] ||= begin
          ports, mappings = Models::Placeholder::PlaceholderBuilder.service_ports(service_models, base)
          slug = service_models.map { |m| model_slug(m) }.join('_')
          task_model("stub_#{slug}", ports: ports.values, base: base) do |task|
            service_models.each_with_index { |srv, i| task.provides(srv, mappings[i], as: "srv#{i}") }
          end
        end
      end

      def bus_ports(type)
        [Syskit::DynamicPort.new(/^\w+$/, :output, type), Syskit::DynamicPort.new(/^w\w+$/, :input, type)]
      end

      def task_model(name, ports: [], dynamic: [], base: nil)
        spec = Orogen::TaskSpec.new("stubs::#{name}", nil)
        spec.superclass = base.spec if base
        ports.each { |p| spec.ports[p.name] = p unless base&.find_port(p.name) }
        spec.dynamic_ports.concat(dynamic)
        spec.finalize
        model = (base || TaskContext).new_model(spec)
        yield(model)
        model
      end

      def model_slug(model)
        Naming.underscore(model.name.to_s.split('::').last.to_s.gsub(/\W/, '_'))
      end
    end
  end
end
