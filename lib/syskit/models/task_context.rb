# frozen_string_literal: true

require 'syskit/models/component'
require 'syskit/models/port_lookup'
require 'syskit/models/dynamic_services'
require 'syskit/models/task_specialization'
require 'syskit/models/task_context_orogen'
require 'syskit/models/task_state_events'
require 'syskit/models/configuration_hooks'

module Syskit
  module Models
    # The class-level side of task models. Every task context of a loaded
    # .orogen file is a subclass of Syskit::TaskContext extended with this
    # module, so that +Syskit.extend_model OroGen.lib.Task do ... end+ is a
    # plain +class_eval+: +driver_for+, +provides+ and +stub+ are class
    # methods, +def configure+ defines the method the generator runs.
    module TaskContext
      include Component
      include PortLookup
      include PortModelLookups
      include DynamicServices
      include TaskSpecialization
      include TaskContextOrogen
      include TaskStateEvents
      include ConfigurationHooks

      attr_reader :spec

      # A submodel made in Ruby (see Component#new_submodel);
      # +orogen_model_name:+ names its oroGen model ('lib::Task'), as
      # Syskit's +TaskContext.new_submodel(orogen_model_name: ...)+ does.
      # With +orogen_model:+ (an Orogen::ModelView), the submodel stands for
      # that oroGen model (see #define_from_orogen).
      def new_submodel(orogen_model_name: nil, orogen_model: nil, **options, &block)
        return new_model(orogen_model.spec, orogen_model: orogen_model) if orogen_model

        model = super(**options, &block)
        model.spec.orogen_model_name = orogen_model_name if orogen_model_name
        model
      end

      # A new task model for +spec+, subclassing this one; +orogen_model+
      # is the view of +spec+ it is known by, when one was made already.
      def new_model(spec, orogen_model: nil)
        model = Class.new(self)
        model.send(:setup_model, spec)
        orogen_model&.model = model
        model.instance_variable_set(:@orogen_model, orogen_model)
        model
      end

      def name
        registered_name || (spec ? spec.name : super)
      end

      def to_s
        name || '#<anonymous task model>'
      end

      # The name shown to users: #to_s, as Syskit's models have it.
      def short_name
        to_s
      end

      def inspect
        name
      end

      def abstract?
        spec&.abstract?
      end

      # What the .orogen file's transformer block declares (frames,
      # transformations, the ports that carry them), nil without one. (A
      # block given in Ruby is not modelled: see Compat::TaskStatements.)
      def transformer
        spec&.transformer
      end

      # The transformation (+from+, +to+ frame names) the port +port+ (a
      # port or its name) carries, as the .orogen file declares it.
      def find_transform_of_port(port)
        spec&.transformer&.find_transform_of_port(port)
      end

      # The frame the data of +port+ is expressed in, as declared.
      def find_frame_of_port(port)
        spec&.transformer&.find_frame_of_port(port)
      end

      # What the .orogen file says of this model, as Syskit's orogen_model:
      # +orogen_model.find_port('command').multiplexes+ changes a port.
      def orogen_model
        @orogen_model ||= Orogen::ModelView.new(spec, model: self)
      end

      # Static ports by name (inherited ones included).
      def ports
        spec ? spec.all_ports : {}
      end

      # A port of this model is its own component port (Syskit's name).
      def self_port_to_component_port(port)
        port
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

      # Stands for what the real component does at configure time, when
      # the network is generated without it (e.g. creating per-device ports
      # from the property the configure method just set).
      def stub(&block)
        (@stub_blocks ||= []) << block
        Component.declarations_changed
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

      # The sections of configuration of the model, from the app's
      # configuration files (App#configuration_manager): those of the
      # concrete model for a specialization.
      def configuration_manager
        Syskit.app.configuration_manager(concrete_model)
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
        @component_class ||= OrocosTask.for(self)
      end

      private

      def setup_model(spec)
        @spec = spec
        define_port_readers(spec)
        define_event_readers
        @services = {}
        @stub_blocks = []
      end

      # +out_port+ on the model (its Models::Port) and on the tasks
      # (theirs, a Syskit::Port), for each static port of the spec.
      def define_port_readers(spec)
        spec.all_ports.each_key { |name| define_port_reader(name) }
        spec.all_properties.each_key { |name| define_property_reader(name) }
      end

      # +task.<name>_property+, the task's Property.
      def define_property_reader(name)
        reader = "#{name}_property"
        define_method(reader) { property(name) } unless method_defined?(reader)
      end

      def define_port_reader(name)
        reader = "#{name}_port"
        unless singleton_class.method_defined?(reader)
          define_singleton_method(reader) { find_input_port(name) || find_output_port(name) }
        end
        define_method(reader) { find_port(name) } unless method_defined?(reader)
      end

      def add_service(...)
        srv = super
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
    end
  end
end
