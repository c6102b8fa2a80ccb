# frozen_string_literal: true

module Syskit
  module Models
    # The ports of a task model's service, as Syskit's bound data service
    # models give them: +find_port+ and +ports+ give, for each port of the
    # service model, the declaration of the task port it is mapped to; the
    # port models (+Task.gps_srv.pose_port+, +find_output_port+,
    # +each_input_port+) are the service's ports, named as the service
    # names them, whose +to_component_port+ is the task model's port.
    # Part of BoundDataService.
    module BoundDataServicePorts
      include PortLookup

      def find_output_port(name)
        port = find_port(name)
        service_port_model(name.to_s, port) if port&.output?
      end

      def find_input_port(name)
        port = find_port(name)
        service_port_model(name.to_s, port) if port&.input?
      end

      # Its input (output) port models, in the service model's order.
      def each_input_port
        return enum_for(__method__) unless block_given?

        ports.each { |name, port| yield service_port_model(name, port) if port.input? }
      end

      def each_output_port
        return enum_for(__method__) unless block_given?

        ports.each { |name, port| yield service_port_model(name, port) if port.output? }
      end

      # +{service port name => task port name}+, for every port of the
      # service model (Syskit's +port_mappings_for_task+).
      def port_mappings_for_task
        port_mappings.dup
      end

      # +{port name of srv_model => task port name}+, for +srv_model+ the
      # service's model or one it provides.
      def port_mappings_for(srv_model)
        model.port_mappings_for(srv_model).transform_values { |name| port_mappings.fetch(name) }
      end

      # +{service port name => task port}+: the task port (a Models::Port of
      # the task model) behind each port of the service model, in its order. Syskit's lookups (find_port,
      # find_input_port, has_port?, each_port...) read it (PortLookup).
      def ports
        model.ports.each_key.filter_map do |name|
          (task = port_mappings[name]) && [name, task_model.find_port(task)]
        end.to_h
      end

      # The task model's port (a Models::Port) behind a port of the service
      # model (a port object or its name).
      def self_port_to_component_port(port)
        found = find_port(port.respond_to?(:name) ? port.name : port)
        return task_model.find_output_port(found.name) || task_model.find_input_port(found.name) if found

        raise DeclarationError.new("#{model} has no port #{port.respond_to?(:name) ? port.name : port}",
                                   location: Location.of_caller,
                                   hint: "its ports: #{model.ports.keys.sort.join(', ')}")
      end

      # The port of this service that the task port +task_port+ (an object
      # or its name) stands for, or nil.
      def find_port_for_task_port(task_port)
        task_port_name = task_port.respond_to?(:name) ? task_port.name : task_port.to_s
        srv_port_name, = port_mappings.find { |_, name| name == task_port_name }
        find_output_port(srv_port_name) || find_input_port(srv_port_name) if srv_port_name
      end

      # The reader of a slave service, made when the slave is declared
      # (+stereo_srv.left_srv+).
      def define_slave_reader(slave)
        reader = "#{slave.name}_srv"
        define_singleton_method(reader) { slave } unless respond_to?(reader)
      end

      private

      # +name_port+ for each port of the service model.
      def define_port_readers
        model.ports.each_key do |name|
          reader = "#{name}_port"
          define_singleton_method(reader) { find_output_port(name) || find_input_port(name) } unless respond_to?(reader)
        end
      end

      # The port model of the service port +name+ (declared by the task
      # port +port+), one per name.
      def service_port_model(name, port)
        (@port_models ||= {})[name] ||= (port.input? ? InputPort : OutputPort).new(self, port, name)
      end
    end
  end
end
