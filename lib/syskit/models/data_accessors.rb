# frozen_string_literal: true

module Syskit
  module Models
    # What a component model declares of the data it reads and writes
    # while it runs (Syskit's model-level +data_reader+ / +data_writer+):
    # a port of one of its children, of another model, or a port query
    # (+OtherTask.match.out_port+), under a name. Each task of the model
    # then has an accessor of that name (+task.pose_reader+, see
    # Syskit::DynamicPortBinding); reading and writing through it needs
    # Syskit's runtime. Part of Component.
    module DataAccessors
      # Declares a reader of the output port +port+, named +as+.
      def data_reader(port, as:)
        declare_data_accessor(port, as.to_s, :output, DynamicPortBinding::BoundOutputReader, Location.of_caller)
      end

      # Declares a writer to the input port +port+, named +as+.
      def data_writer(port, as:)
        declare_data_accessor(port, as.to_s, :input, DynamicPortBinding::BoundInputWriter, Location.of_caller)
      end

      # The readers (writers) declared on this model and its parents, by name.
      def data_readers
        inherited_accessors(:data_readers)
      end

      def data_writers
        inherited_accessors(:data_writers)
      end

      def each_data_reader(&)
        data_readers.each_value(&)
      end

      def each_data_writer(&)
        data_writers.each_value(&)
      end

      def find_data_reader(name)
        data_readers[name.to_s]
      end

      def find_data_writer(name)
        data_writers[name.to_s]
      end

      private

      def inherited_accessors(kind)
        inherited = superclass.respond_to?(kind) ? superclass.public_send(kind) : {}
        own = instance_variable_get(:"@#{kind}")
        own ? inherited.merge(own) : inherited
      end

      def declare_data_accessor(port, name, direction, accessor_class, location)
        check_accessor_direction(port, direction, location)
        accessor = accessor_class.new(name, port, self, location)
        suffix = direction == :output ? 'reader' : 'writer'
        (instance_variable_get(:"@data_#{suffix}s") || instance_variable_set(:"@data_#{suffix}s", {}))[name] = accessor
        define_accessor_reader(name, suffix)
        accessor
      end

      # +name_reader+ (+name_writer+) on the model's tasks.
      def define_accessor_reader(name, suffix)
        reader = "#{name}_#{suffix}"
        find = :"find_data_#{suffix}"
        define_method(reader) { public_send(find, name) } unless method_defined?(reader, false)
      end

      def check_accessor_direction(port, direction, location)
        found = accessor_direction(port, location)
        return if found.nil? || found == direction

        statement = direction == :output ? 'data_reader' : 'data_writer'
        raise InvalidArgument.new("#{port} is an #{found} port, #{statement} expects an #{direction} port",
                                  location: location,
                                  hint: 'data_reader reads an output port, data_writer writes an input port')
      end

      # :output or :input for a port or port query, nil when a query
      # cannot tell without a plan.
      def accessor_direction(port, location)
        return port.try_resolve_direction if port.respond_to?(:try_resolve_direction)
        return port.output? ? :output : :input if port.respond_to?(:output?)

        raise InvalidArgument.new("#{port.inspect} is not a port",
                                  location: location, hint: 'give a port (Task.out_port) or a port query')
      end
    end

    # Syskit's model-level port bindings: the readers and writers declared
    # by DataAccessors.
    module DynamicPortBinding
      # A reader or writer declared on +component_model+: its name and the
      # port (or port query) it accesses.
      class BoundAccessor
        attr_reader :name, :port, :component_model, :declared_at

        def initialize(name, port, component_model, location)
          @name = name
          @port = port
          @component_model = component_model
          @declared_at = location
          freeze
        end

        def to_s
          "#{component_model}.#{name}"
        end
      end

      # A reader: what +task.name_reader+ is made from.
      class BoundOutputReader < BoundAccessor
        # The reader of +task+ (a task of the model) this declares.
        def instanciate(task)
          Syskit::DynamicPortBinding::BoundOutputReader.new(self, task)
        end
      end

      # A writer: what +task.name_writer+ is made from.
      class BoundInputWriter < BoundAccessor
        def instanciate(task)
          Syskit::DynamicPortBinding::BoundInputWriter.new(self, task)
        end
      end
    end
  end
end
