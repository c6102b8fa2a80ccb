# frozen_string_literal: true

require 'syskit/models/data_accessors'

module Syskit
  # The readers and writers of a task, as its model declares them
  # (Models::DataAccessors): +task.pose_reader+ is one object per task and
  # name. What they read or write, and the port they are bound to, are
  # known only while Syskit's runtime runs the task.
  module DynamicPortBinding
    # The accessor +model+ (a Models::DynamicPortBinding::BoundAccessor)
    # of +component+.
    class BoundAccessor
      attr_reader :model, :component

      def initialize(model, component)
        @model = model
        @component = component
      end

      def name
        model.name
      end

      # The port (or port query) it accesses.
      def port
        model.port
      end

      def to_s
        "#{component}.#{name}"
      end
      alias inspect to_s
    end

    class BoundOutputReader < BoundAccessor; end
    class BoundInputWriter < BoundAccessor; end

    # The accessors of a task. Part of Component.
    module ComponentAccessors
      # The reader +name+ its model declares (see Models::DataAccessors),
      # nil if none.
      def find_data_reader(name)
        find_data_accessor(:find_data_reader, name)
      end

      def find_data_writer(name)
        find_data_accessor(:find_data_writer, name)
      end

      def each_data_reader
        return enum_for(__method__) unless block_given?

        model.each_data_reader { |m| yield find_data_reader(m.name) }
      end

      def each_data_writer
        return enum_for(__method__) unless block_given?

        model.each_data_writer { |m| yield find_data_writer(m.name) }
      end

      private

      def find_data_accessor(lookup, name)
        accessors = (@data_accessors ||= {})
        key = [lookup, name.to_s]
        return accessors[key] if accessors.key?(key)

        accessors[key] = model.public_send(lookup, name)&.instanciate(self)
      end
    end
  end
end
