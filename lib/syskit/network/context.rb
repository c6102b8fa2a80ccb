# frozen_string_literal: true

module Syskit
  module Network
    # The network being generated, shared by the generator's steps: each
    # step reads what the previous ones built and adds its part.
    class Context
      # How a device's driver talks to its bus's driver (see Buses).
      BusLink = Struct.new(:device, :bus_task, :device_task, :bus_output, :bus_input, :client_input, :client_output)

      # A port the bus driver must have for one device, created at configure time.
      ExpectedPort = Struct.new(:name, :direction, :type, :device)

      attr_reader :app, :profile, :robot_config, :requirements, :tasks, :bus_links,
                  :expected_ports, :connections, :errors, :roots, :compositions
      # The configure and start steps (Plan::Step), and the tasks in the
      # order they are configured (see Order).
      attr_accessor :order, :configure_order, :stub_deployments

      def initialize(app:, requirements:, profile: nil, robot_config: nil, stub_deployments: false)
        @app = app
        @profile = profile
        @robot_config = robot_config
        @requirements = requirements
        @stub_deployments = stub_deployments
        @tasks = []
        @roots = []
        @compositions = []
        @task_by_device = {}.compare_by_identity
        @bus_links = []
        @expected_ports = Hash.new { |h, k| h[k] = [] }.compare_by_identity
        @connections = []
        @errors = []
      end

      # The task contexts sorted by (deployed) name, once: the order and
      # the plan both list tasks by name. (A plain Syskit::Component is
      # not deployed, configured or started: it has no name.)
      def tasks_by_name
        @tasks_by_name ||= @tasks.grep(TaskContext).sort_by(&:name)
      end

      # Adds a task made for +requirement+ (for +device+, when it drives one).
      def add_task(task, device, requirement)
        @tasks << task
        @task_by_device[device] = task if device
        task.requirements = requirement
        task
      end

      # The task of +device+; a slave device's is its master's.
      def task_for(device)
        @task_by_device[device] || ((master = device.master_device) && @task_by_device[master])
      end

      def requirement_for(task)
        task.requirements
      end

      # The device a task was created for (nil for a task of a composition
      # that drives no device).
      def device_of(task)
        task.requirements.device
      end

      # Collects an error; the step raises them all at its end.
      def error(error)
        @errors << error
        nil
      end

      def raise_errors
        errors = @errors
        @errors = []
        ErrorList.raise_if_any(errors)
      end
    end
  end
end
