# frozen_string_literal: true

module Syskit
  module Orogen
    # A deployment: a process that runs named task instances. Declared in an
    # .orogen file (+deployment 'test_canbus' do task('can0', 'canbus::Task') end+)
    # or made for one task by +Syskit.conf.use_deployment OroGen.x.Task => 'name'+.
    class DeploymentSpec
      # One task instance of a deployment (oroGen's task activity). Made by
      # position: one per deployed task of a robot, and a keyword Struct
      # costs a hash each.
      DeployedTask = Struct.new(:name, :model, :deployment, :declared_at) do
        def to_s
          "#{name} (#{model.name}, deployment #{deployment.name})"
        end

        # oroGen's name for the task context model it runs.
        def context
          model.orogen_model
        end
      end

      # The task instances, in declaration order (oroGen's name).
      attr_reader :name, :task_activities, :declared_at

      # +location+: where it is declared (by position: one is made for
      # every +use_deployment Task => 'name'+, and keywords given to +new+
      # cost a hash each). +unmanaged:+ a process started outside of
      # Syskit (a device's deployed_as_unmanaged).
      def initialize(name, location = nil, unmanaged: false)
        @name = name
        @task_activities = []
        @declared_at = location
        @unmanaged = unmanaged
      end

      def unmanaged?
        @unmanaged
      end

      # A copy whose task names start with +prefix+ (use_deployment's
      # 'deployment' => 'prefix' form).
      def with_prefix(prefix)
        with_name_mappings(task_activities.to_h { |t| [t.name, "#{prefix}#{t.name}"] }, name: "#{prefix}#{name}")
      end

      # A copy whose tasks are renamed by +mappings+ (deployed name =>
      # new name; the others keep theirs): what a robot configures.
      def with_name_mappings(mappings, name: self.name)
        copy = DeploymentSpec.new(name, declared_at, unmanaged: unmanaged?)
        task_activities.each { |t| copy.add_task(mappings.fetch(t.name, t.name), t.model, location: t.declared_at) }
        copy
      end

      def add_task(name, model, location: nil)
        task = DeployedTask.new(name, model, self, location)
        @task_activities << task
        task
      end

      # oroGen's statement: +task 'name', TaskModel+ (in a
      # Syskit::Deployment.new_submodel block, or on a spec made in Ruby).
      def task(name, model)
        add_task(name.to_s, model, location: Location.of_caller)
      end
    end
  end
end
