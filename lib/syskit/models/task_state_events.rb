# frozen_string_literal: true

module Syskit
  module Models
    # An event of a task model, as Roby models them (here, the events of
    # the task's states): whether it ends the task, and the event it is
    # forwarded to (a custom error state's event to +runtime_error+).
    class TaskEvent
      attr_reader :symbol, :forwarded_to

      def initialize(symbol, terminal:, forwarded_to: nil)
        @symbol = symbol
        @terminal = terminal
        @forwarded_to = forwarded_to
      end

      def terminal?
        @terminal
      end

      # Events are values: made again on each lookup, equal when the same.
      def ==(other)
        other.is_a?(TaskEvent) && to_a == other.to_a
      end

      def to_a
        [symbol, terminal?, forwarded_to]
      end
      alias eql? ==

      def hash
        [TaskEvent, *to_a].hash
      end

      def to_s
        "#{symbol}_event"
      end
    end

    # The events of a task model's states, as Syskit makes them: RTT's
    # states have an event each (+exception+ and +fatal_error+ end the
    # task), and each state its oroGen model declares one named after it,
    # forwarded to RTT's of its kind (see FORWARDED_TO) and terminal when
    # that one is. Each event has a reader on the model and on its tasks
    # (+custom_error_event+).
    module TaskStateEvents
      # The states every task context has (RTT's), which have an event;
      # PRE_OPERATIONAL has none.
      RTT_STATES_WITH_EVENTS = %w[STOPPED RUNNING RUNTIME_ERROR EXCEPTION FATAL_ERROR].freeze

      # RTT's events that end the task.
      TERMINAL = %i[exception fatal_error].freeze

      # The RTT event the events of each kind of declared state go to.
      FORWARDED_TO = { error_states: :runtime_error, exception_states: :exception, fatal_states: :fatal_error }.freeze

      # The event emitted when a task enters each of its model's states, by
      # state name (+:CUSTOM => :custom+): RTT's, then those of its spec and
      # of the specs it inherits (+runtime_states+, +error_states+...).
      def state_events
        names = RTT_STATES_WITH_EVENTS + declared_states.map(&:first)
        names.to_h { |name| [name.to_sym, event_symbol(name)] }
      end

      # The event of the state +name+ (+:EXCEPTION+), nil when it has none.
      def find_state_event(name)
        state_events[name.to_sym]
      end

      # The events of the model's states (Models::TaskEvent), by symbol.
      def events
        found = RTT_STATES_WITH_EVENTS.to_h do |name|
          symbol = event_symbol(name)
          [symbol, TaskEvent.new(symbol, terminal: TERMINAL.include?(symbol))]
        end
        declared_states.each do |name, kind|
          symbol = event_symbol(name)
          target = FORWARDED_TO[kind]
          found[symbol] = TaskEvent.new(symbol, terminal: TERMINAL.include?(target), forwarded_to: target)
        end
        found
      end

      # The event called +symbol+ (+:custom_error+), nil when there is none.
      def find_event(symbol)
        events[symbol.to_sym]
      end

      # Defines the +<event>_event+ readers of the model and its tasks for
      # the events it does not have a reader of yet.
      def define_event_readers
        events.each_key do |symbol|
          reader = "#{symbol}_event"
          define_singleton_method(reader) { find_event(symbol) } unless singleton_class.method_defined?(reader)
          next if method_defined?(reader)

          define_method(reader) { TaskEventGenerator.new(self, model.find_event(symbol)) }
        end
      end

      private

      def event_symbol(state_name)
        Naming.underscore(state_name).downcase.to_sym
      end

      # The states its spec and the specs it inherits declare, as
      # [name, kind] pairs, the inherited ones first.
      def declared_states(from = spec)
        return [] unless from

        declared_states(from.superclass) + from.states.flat_map { |kind, names| names.map { |n| [n, kind] } }
      end
    end
  end
end
