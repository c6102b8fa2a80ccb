# frozen_string_literal: true

require 'syskit/network/stub_models'
require 'syskit/network/selection'
require 'syskit/network/instantiation_errors'
require 'syskit/network/instantiate'
require 'syskit/network/merge'
require 'syskit/network/context'
require 'syskit/network/drivers'
require 'syskit/network/buses'
require 'syskit/network/deploy'
require 'syskit/network/order'
require 'syskit/network/configure'
require 'syskit/network/policy'
require 'syskit/network/connect'
require 'syskit/network/plan'

module Syskit
  module Network
    # Turns requirements (a profile's device actions and definitions) into a
    # network of configured tasks and its Plan. Each step is a class of its own, run in
    # this order; a step's errors are all reported together.
    class Generator
      STEPS = [Instantiate, Merge, Buses, Deploy, Order, Configure, Connect].freeze

      # What generation gives: the plan, the configured tasks, and how long
      # each step took (seconds, by step name).
      Result = Struct.new(:plan, :context, :timings) do
        def tasks
          context.tasks
        end

        # The task of a device, or of a requirement's device. (A bus answers
        # #device too: can0.device(Model, as: ...) declares one on it.)
        def task_for(device)
          context.task_for(device.is_a?(InstanceRequirements) ? device.device : device)
        end
      end

      # The plan of +profile+ on +robot+: every device, or the given actions
      # ('gps_dev', 'gps'). +before_step+: see #generate.
      def self.plan_profile(app, profile, actions: [], robot: 'default', before_step: nil)
        requirements =
          if actions.empty?
            profile.all_requirements
          else
            actions.map { |a| profile.find_action(a) || raise(unknown_action(profile, a)) }
          end
        new(app, requirements, profile: profile, robot_config: app.robot_config(robot))
          .generate(before_step: before_step)
      end

      def self.unknown_action(profile, name)
        actions = profile.action_names
        UnknownName.new("#{profile} has no action '#{name}'#{Naming.did_you_mean(name, actions)}",
                        location: profile.declared_at, hint: "its actions are #{actions.join(', ')}")
      end

      # +stub_deployments+ (tests): each task gets a deployment of its own;
      # +stub_abstract+ (tests): abstract children are filled with stubs.
      def initialize(app, requirements, profile: nil, robot_config: nil, stub_deployments: false,
                     stub_abstract: false)
        @context = Context.new(app: app, requirements: requirements, profile: profile,
                               robot_config: robot_config, stub_deployments: stub_deployments)
        @stub_abstract = stub_abstract
      end

      # Runs the steps (all of them, or up to and including +through+) and
      # builds the plan when all ran. +before_step+, when given, is called
      # before each step and before the plan is built, outside of the
      # timings (the benchmark empties the CPU caches there).
      def generate(through: STEPS.last, before_step: nil)
        timings = {}
        STEPS[0..STEPS.index(through)].each do |step|
          before_step&.call
          timings[Naming.underscore(step.name.split('::').last)] = measure { step_for(step).run }
          @context.raise_errors
        end
        return Result.new(nil, @context, timings) unless through == STEPS.last

        before_step&.call
        plan = nil
        timings['plan'] = measure { plan = Plan.build(@context) }
        Result.new(plan, @context, timings)
      end

      private

      def step_for(step)
        step == Instantiate ? step.new(@context, stub_abstract: @stub_abstract) : step.new(@context)
      end

      def measure
        start = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        yield
        Process.clock_gettime(Process::CLOCK_MONOTONIC) - start
      end
    end
  end
end
