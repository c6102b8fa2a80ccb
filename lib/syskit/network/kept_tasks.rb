# frozen_string_literal: true

module Syskit
  module Network
    class Merge
      # The tasks a merge group keeps, in order, indexed so that the first
      # one whose inputs agree with a task's (see Merge#inputs) is found by
      # hash lookups: one per distinct set of connected ports among the
      # kept tasks (tasks of one model made for the same child have the
      # same), whatever the number of tasks.
      #
      # Two tasks agree when their inputs are the same on the ports both
      # have connected: kept tasks with ports S agree with a task whose
      # ports are T when their sources on S & T are its sources there.
      class KeptTasks
        def initialize
          @tasks = []
          @inputs = []
          # Sorted port names => indexes of the kept tasks with those ports.
          @by_ports = {}
          # [ports, common ports] => { sources on the common ports => first
          # index }, built when a task with such ports is first looked up.
          @indexes = {}
        end

        def size
          @tasks.size
        end

        # Keeps +task+, whose inputs are +inputs+ (port => sources).
        def add(task, inputs)
          index = @tasks.size
          @tasks << task
          @inputs << inputs
          ports = inputs.keys.sort
          (@by_ports[ports] ||= []) << index
          @indexes.each do |(set, common), by_sources|
            by_sources[inputs.values_at(*common)] ||= index if set == ports
          end
        end

        # The first kept task whose inputs agree with +inputs+, or nil.
        def first_agreeing(inputs)
          ports = inputs.keys
          first = nil
          @by_ports.each do |set, members|
            common = set & ports
            index = (@indexes[[set, common]] ||= build(members, common))[inputs.values_at(*common)]
            first = index if index && (first.nil? || index < first)
          end
          first && @tasks[first]
        end

        private

        def build(members, common)
          members.each_with_object({}) { |i, by_sources| by_sources[@inputs[i].values_at(*common)] ||= i }
        end
      end
    end
  end
end
