# frozen_string_literal: true

require 'syskit/models/bound_service'
require 'syskit/models/port_mapper'
require 'syskit/models/task_arguments'
require 'syskit/models/driver_services'
require 'syskit/models/task_requirements'
require 'syskit/models/dynamic_services'
require 'syskit/models/not_a_model'

module Syskit
  module Models
    # The class-level side of task models. Every task context of a loaded
    # .orogen file is a subclass of Syskit::TaskContext extended with this
    # module, so that +Syskit.extend_model OroGen.lib.Task do ... end+ is a
    # plain +class_eval+: +driver_for+, +provides+ and +stub+ are class
    # methods, +def configure+ defines the method the generator runs.
    module TaskModel
      include DynamicServices
      include TaskArguments
      include DriverServices
      include TaskRequirementStatements

      attr_reader :spec

      class << self
        # Bumped whenever a task model gains a service or a stub: the cached
        # views below (which merge a model's declarations with its parents')
        # are then computed again.
        def declarations_version
          @declarations_version ||= 0
        end

        def declarations_changed
          @declarations_version = declarations_version + 1
        end
      end

      # A new task model for +spec+, subclassing this one.
      def new_model(spec)
        model = Class.new(self)
        model.send(:setup_model, spec)
        model
      end

      def name
        spec ? spec.name : super
      end

      def to_s
        name
      end

      def inspect
        name
      end

      def abstract?
        spec&.abstract?
      end

      # What the .orogen file says of this model, as Syskit's orogen_model:
      # +orogen_model.find_port('command').multiplexes+ changes a port.
      def orogen_model
        Orogen::ModelView.new(spec)
      end

      # Static ports by name (inherited ones included).
      def ports
        spec ? spec.all_ports : {}
      end

      def find_port(name)
        ports[name.to_s]
      end

      # Syskit's port lookups, with oroGen's port modifiers
      # (+find_output_port('pose').triggered_once_per_update+); nil when
      # there is no such port.
      def find_output_port(name)
        port = find_port(name)
        PortModifiers.new(port) if port&.output?
      end

      def find_input_port(name)
        port = find_port(name)
        PortModifiers.new(port) if port&.input?
      end

      # Static ports of +direction+ and +type+, sorted by name.
      def static_ports_of(direction, type)
        cached(direction, type) do
          ports.values.select { |p| p.direction == direction && p.type == type }.sort_by(&:name).freeze
        end
      end

      def dynamic_ports
        spec ? spec.all_dynamic_ports : []
      end

      # Property declarations by name (inherited ones included).
      def property_declarations
        spec ? spec.all_properties : {}
      end

      # Services by name, inherited ones included.
      def services
        cached(:services) do
          inherited = superclass.respond_to?(:services) ? superclass.services : {}
          inherited.merge(@services || {}).freeze
        end
      end

      # Services whose model is or provides +service_model+, in declaration order.
      def services_fulfilling(service_model)
        cached(:fulfilling, service_model) { services.values.select { |srv| srv.fullfills?(service_model) }.freeze }
      end

      # The service of full name +name+ ('gps', or 'stereo.left' for a slave).
      def find_service(name)
        services[name.to_s]
      end
      alias find_data_service find_service

      # Enumerates the services, inherited ones included, in declaration order.
      def each_data_service(&)
        services.each_value(&)
      end

      # Declares that this task drives devices of +model+; the device is given
      # to the task as its +<as>_dev+ argument. Ports of the device model are
      # bound by name and type, or by +'device_port' => 'task_port'+ mappings
      # (keywords or a hash). +slave_of: 'master'+ makes it a slave device
      # of the master service's device (see Robot::SlaveDevice).
      def driver_for(model, mappings = {}, as: nil, slave_of: nil, **more)
        location = Location.of_caller
        unless model.is_a?(DeviceModel)
          hint = if model.is_a?(DataServiceModel) then "#{model} is a data service: use provides #{model}, as: 'name'"
                 else NotAModel.hint('driver_for', model, location)
                 end
          raise DeclarationError.new("driver_for expects a device or bus model, got #{model.inspect}",
                                     location: location, hint: hint)
        end

        as ||= Naming.underscore(model.name.to_s.split('::').last)
        add_service(as, model, mappings.merge(more), location, slave_of: slave_of)
      end

      # Declares that this task provides the data service +model+ under the
      # name +as+, with optional +'service_port' => 'task_port'+ mappings;
      # +slave_of: 'name'+ makes it a slave of the service +name+ (its full
      # name is then +name.as+).
      def provides(model, mappings = {}, as: nil, slave_of: nil, **more)
        location = Location.of_caller
        return (@task_services ||= []) << model if model.is_a?(Compat::TaskService) && as.nil?

        unless model.is_a?(DataServiceModel)
          raise DeclarationError.new("provides expects a data service model, got #{model.inspect}",
                                     location: location, hint: NotAModel.hint('provides', model, location))
        end
        unless as
          raise DeclarationError.new("provides #{model} needs a service name",
                                     location: location, hint: "write provides #{model}, as: 'name'")
        end

        add_service(as, model, mappings.merge(more), location, slave_of: slave_of)
      end

      # Stands for what the real component does at configure time, when
      # the network is generated without it (e.g. creating per-device ports
      # from the property the configure method just set).
      def stub(&block)
        (@stub_blocks ||= []) << block
        TaskModel.declarations_changed
        block
      end

      def stub_blocks
        cached(:stub_blocks) do
          inherited = superclass.respond_to?(:stub_blocks) ? superclass.stub_blocks : []
          (inherited + (@stub_blocks || [])).freeze
        end
      end

      # Timing statement of real bundles; recorded, used to size buffers.
      def worstcase_processing_time(seconds = nil)
        return @worstcase_processing_time || spec&.worstcase_processing_time if seconds.nil?

        @worstcase_processing_time = seconds
      end

      # The class of this model's +properties+ objects.
      def properties_class
        @properties_class ||= Properties.for(self)
      end

      # Operations by name (inherited ones included).
      def operations
        spec ? spec.all_operations : {}
      end

      # The class of the task's component (+orocos_task+, and what +stub+
      # blocks are evaluated on).
      def component_class
        @component_class ||= Component.for(self)
      end

      private

      # A view computed once per +key+ (and +subkey+), until declarations change.
      def cached(key, subkey = nil)
        version = TaskModel.declarations_version
        if @cache_version != version
          @cache = {}
          @cache_version = version
        end
        table = subkey.nil? ? @cache : (@cache[key] ||= {}.compare_by_identity)
        slot = subkey.nil? ? key : subkey
        table.fetch(slot) { table[slot] = yield }
      end

      def setup_model(spec)
        @spec = spec
        @services = {}
        @stub_blocks = []
      end

      def add_service(name, model, mappings, location, slave_of: nil)
        name = name.to_s
        check_service_options(name, mappings, location)
        master = master_service(slave_of, location) if slave_of
        full_name = master ? "#{master.full_name}.#{name}" : name
        existing = find_service(full_name)
        if existing
          raise DeclarationError.new("#{self.name} already has a #{existing} declared at #{existing.declared_at}",
                                     location: location, hint: "give this one another name with as: 'other_name'")
        end

        port_mappings = PortMapper.new(self, model, mappings, location).map
        srv = BoundService.new(self, name, model, port_mappings, location, master: master)
        (@services ||= {})[full_name] = srv
        TaskModel.declarations_changed
        define_device_reader(srv) if srv.driven_device_model
        srv
      end

      # +<name>_dev+: a master service's device is a task argument; a slave's
      # is found from its master's device.
      def define_device_reader(srv)
        argument = srv.argument_name
        if srv.master?
          define_method(argument) { arguments[argument] }
        else
          define_method(argument) { find_device_attached_to(srv) }
        end
      end

      def master_service(slave_of, location)
        name = slave_of.respond_to?(:full_name) ? slave_of.full_name : slave_of.to_s
        found = find_service(name)
        return found if found

        known = services.keys.sort
        hint = known.empty? ? "declare the master first: driver_for Model, as: 'name'" : "services: #{known.join(', ')}"
        raise DeclarationError.new(
          "slave_of: '#{name}' names no service of #{self.name}#{Naming.did_you_mean(name, known)}",
          location: location, hint: hint
        )
      end

      def check_service_options(name, mappings, location)
        unless name.match?(/\A[a-z_]\w*\z/)
          raise DeclarationError.new("'#{name}' is not a valid service name",
                                     location: location, hint: "use a lower-case name, e.g. as: 'gps'")
        end
        options = mappings.keys.grep(Symbol)
        return if options.empty?

        raise DeclarationError.new(
          "unknown option #{options.map { |o| "#{o}:" }.join(', ')}",
          location: location,
          hint: "the only option is as: 'name'; port mappings are written 'service_port' => 'task_port'"
        )
      end
    end
  end
end
