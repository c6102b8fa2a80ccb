# frozen_string_literal: true

require 'set'

module Syskit
  module NetworkGeneration
    # What is known of how often a port gets data (Syskit's PortDynamics):
    # its triggers, each a named period (in seconds) and the number of
    # samples each time. Requirements carry them for their ports
    # (InstanceRequirements#add_port_period); a value, as data.
    class PortDynamics
      # One source of data on the port: every +period+ seconds,
      # +sample_count+ samples.
      Trigger = Struct.new(:name, :period, :sample_count)

      attr_reader :name, :sample_size, :triggers

      def initialize(name, sample_size = 1)
        @name = name
        @sample_size = sample_size
        @triggers = Set.new
      end

      def initialize_copy(other)
        super
        @triggers = other.triggers.dup
      end

      # Adds a trigger (see Trigger); returns self.
      def add_trigger(name, period, sample_count)
        @triggers << Trigger.new(name, period, sample_count)
        self
      end

      def empty?
        @triggers.empty?
      end

      def ==(other)
        other.is_a?(PortDynamics) && other.name == name && other.sample_size == sample_size &&
          other.triggers == triggers
      end
      alias eql? ==

      def hash
        [PortDynamics, name, sample_size, triggers].hash
      end

      def to_s
        "#{name}: #{triggers.map { |t| "#{t.name} every #{t.period}s (#{t.sample_count})" }.join(', ')}"
      end
      alias inspect to_s
    end
  end
end
