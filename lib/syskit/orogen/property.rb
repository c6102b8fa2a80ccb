# frozen_string_literal: true

module Syskit
  module Orogen
    # A configuration property (or attribute) of a task model.
    class Property
      attr_reader :name, :type, :default
      attr_accessor :doc

      def initialize(name, type, default = nil)
        @name = name
        @type = type
        @default = default
      end

      # The value the property has before any configuration is applied. The
      # spec loader checked at the declaration that the default fits the type.
      def initial_value
        return type.zero if default.nil?

        type.from_ruby(default)
      end
    end

    # Modifiers after a property declaration (+.doc+, +.dynamic+).
    class PropertyModifiers
      def initialize(property)
        @property = property
      end

      def doc(text)
        @property.doc = text
        self
      end

      def dynamic
        self
      end
    end

    # What an activity statement (+periodic(0.01)+, +fd_driven+) returns:
    # its modifiers are accepted, they only matter to a running component.
    class ActivityModifiers
      def doc(_text)
        self
      end
    end

    # An operation (RPC) of a task model, recorded for completeness.
    class Operation
      attr_reader :name, :arguments
      attr_accessor :return_type

      def initialize(name)
        @name = name
        @arguments = []
      end

      def returns(type, _doc = nil)
        @return_type = type
        self
      end

      def argument(name, type, _doc = nil)
        @arguments << [name, type]
        self
      end
      alias arg argument

      # Sets the documentation (and returns self, for chaining), or reads it.
      def doc(text = nil)
        return @doc if text.nil?

        @doc = text
        self
      end

      def runs_in_caller_thread
        self
      end
    end
  end
end
