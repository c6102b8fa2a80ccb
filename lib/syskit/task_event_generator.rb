# frozen_string_literal: true

module Syskit
  # An event of a task (Roby's TaskEventGenerator), here one of its states'
  # (see Models::TaskStateEvents): what its model says of it, and the
  # task's event it is forwarded to. Emitting it is the runtime's.
  class TaskEventGenerator
    attr_reader :task, :model

    def initialize(task, model)
      @task = task
      @model = model
    end

    def symbol
      model.symbol
    end

    def terminal?
      model.terminal?
    end

    # Whether +other+ is a child of this event in +relation+ (Roby's
    # +EventStructure::Forwarding+): the task's event it is forwarded to.
    def child_object?(other, relation)
      relation.equal?(Compat::Roby::EventStructure::Forwarding) && other.is_a?(TaskEventGenerator) &&
        other.task.equal?(task) && other.symbol == model.forwarded_to
    end

    def ==(other)
      other.is_a?(TaskEventGenerator) && other.task.equal?(task) && other.symbol == symbol
    end
    alias eql? ==

    def hash
      [task, symbol].hash
    end

    def to_s
      "#{task}.#{symbol}_event"
    end
    alias inspect to_s
  end

  module Compat
    module Roby
      # Roby's relations between events; Forwarding is the one task models
      # declare for their states (see TaskEventGenerator#child_object?).
      module EventStructure
        Forwarding = Module.new
        Forwarding.define_singleton_method(:to_s) { 'Roby::EventStructure::Forwarding' }
      end
    end
  end
end
