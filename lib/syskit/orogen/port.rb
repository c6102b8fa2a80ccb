# frozen_string_literal: true

require 'syskit/port'

module Syskit
  module Orogen
    # A port as a task library (or a data service model) declares it:
    # name, direction (:input/:output) and type; oroGen's port model, the
    # +orogen_model+ of a Syskit::Models::Port. Dynamic ports are the ones
    # created at configure time.
    class Port
      include ConnectionNeeds

      # +declared_at+: where the port was declared (its line of the .orogen
      # file, of a data service's block, of a task model made in Ruby); nil
      # for the ports syskit makes itself (stubs, placeholders).
      attr_reader :name, :direction, :type, :declared_at

      # +declared_type+: the type name as the declaration wrote it, when it is
      # a typedef of +type+ (/base/commands/Joints for /base/samples/Joints).
      def initialize(name, direction, type, dynamic: false, declared_type: nil, location: nil)
        @name = name
        @direction = direction
        @type = type
        @dynamic = dynamic
        @declared_at = location
        declared = declared_type && Types::Registry.normalize(declared_type) unless declared_type.is_a?(Types::Type)
        @declared_type = declared unless declared == type.name
      end

      def dynamic?
        @dynamic
      end

      # The port of the component (Syskit's +to_component_port+): a task
      # model's port is its own.
      def to_component_port
        self
      end

      # Whether this port can be connected to +other+: an output to an input
      # of the same type (Syskit's +can_connect_to?+).
      def can_connect_to?(other)
        output? && other.input? && type == other.type
      end

      # Its type's name, as oroGen's ports say it (+port.orocos_type_name+).
      def orocos_type_name
        type.name
      end

      # Its type's name (+/double+), as Syskit's port models give it.
      def type_name
        type.name
      end

      # The typedef name the port was declared with, when it is not the
      # type's own name (Typelib shows only the latter); nil otherwise.
      attr_reader :declared_type

      # The type as users read it: the declared name too, when it differs
      # (/base/commands/Joints (= /base/samples/Joints)).
      def type_description
        declared_type ? "#{declared_type} (= #{type.name})" : type.name
      end

      def to_s
        "#{direction} port '#{name}' (#{type_description})"
      end
    end
  end
end
