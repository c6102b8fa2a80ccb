# frozen_string_literal: true

module Syskit
  module Models
    # The ports of a task model's service, as Syskit's bound data service
    # models give them: each port of the service model is the task port it
    # is mapped to (+Task.gps_srv.pose_port+ is the task's port behind the
    # service's 'pose'). Part of BoundDataService.
    module BoundDataServicePorts
      include PortLookup

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

      # The task port behind a port of the service model (a port object
      # or its name).
      def self_port_to_component_port(port)
        found = find_port(port.respond_to?(:name) ? port.name : port)
        return found if found

        raise DeclarationError.new("#{model} has no port #{port.respond_to?(:name) ? port.name : port}",
                                   location: Location.of_caller,
                                   hint: "its ports: #{model.ports.keys.sort.join(', ')}")
      end

      # The port of the service model that the task port +task_port+ (an
      # object or its name) stands for, or nil.
      def find_port_for_task_port(task_port)
        task_port_name = task_port.respond_to?(:name) ? task_port.name : task_port.to_s
        srv_port_name, = port_mappings.find { |_, name| name == task_port_name }
        model.ports[srv_port_name] if srv_port_name
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
          define_singleton_method(reader) { find_port(name) } unless respond_to?(reader)
        end
      end
    end
  end
end
