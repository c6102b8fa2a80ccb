# frozen_string_literal: true

module Syskit
  module Config
    # What is deployed on one robot: the file config/robots/<name>.rb, where
    # +Syskit.conf+ is this object.
    #
    #   Syskit.conf.use_deployment 'test_canbus'              # a deployment of an .orogen file
    #   Syskit.conf.use_deployment OroGen.gps_ublox.Task => 'gps'  # one task, named 'gps'
    class RobotConfig
      attr_reader :name, :deployments

      def initialize(app, name)
        @app = app
        @name = name
        @deployments = []
        @deployed_tasks = {}
      end

      # +on:+ (the host) is accepted and has no effect on plans.
      def use_deployment(*specs, **options)
        location = Location.of_caller
        options.delete(:on)
        # Ruby passes a trailing `Model => 'name'` as keywords.
        specs << options unless options.empty?
        specs.each do |spec|
          case spec
          when String, Symbol then add(named_deployment(spec.to_s, location), location)
          when Hash then spec.each { |model, name| add(task_deployment(model, name, location), location) }
          else raise usage_error(spec, location)
          end
        end
        self
      end

      # Deployed tasks by name.
      def deployed_tasks
        @deployed_tasks.values
      end

      # The deployed tasks that can run a task of +model+ (their model is it
      # or a subclass of it), computed once per model: indexed by name for
      # prefer_deployed_tasks('name'), listed by name when they must be
      # scanned (regexp hints) or shown (errors).
      class Candidates
        attr_reader :by_name

        def initialize(groups)
          @by_name = {}
          groups.each { |tasks| tasks.each { |t| @by_name[t.name] = t } }
        end

        def empty?
          by_name.empty?
        end

        def list
          @list ||= by_name.values.sort_by(&:name).freeze
        end
      end

      def candidates_for(model)
        @candidates ||= {}
        @candidates[model] ||= begin
          @by_model ||= deployed_tasks.group_by(&:model)
          Candidates.new(@by_model.filter_map { |m, tasks| tasks if m <= model })
        end
      end

      # Deployed tasks whose model is +model+ or a subclass of it, by name.
      def deployed_tasks_for(model)
        candidates_for(model).list
      end

      def to_s
        "robot '#{name}'"
      end

      def inspect
        "#<#{self.class.name} #{name}: #{@deployed_tasks.keys.join(', ')}>"
      end

      private

      def add(deployment, location)
        @candidates = nil
        @by_model = nil
        @deployments << deployment
        deployment.tasks.each do |task|
          if (other = @deployed_tasks[task.name])
            raise DeploymentError.new(
              "deployed task name '#{task.name}' is used twice (#{other} and #{task})",
              location: location, hint: 'deployed task names must be unique on a robot: rename one of them'
            )
          end

          @deployed_tasks[task.name] = task
        end
      end

      def named_deployment(name, location)
        found = @app.orogen.find_deployment(name)
        return found if found

        @app.orogen.libraries_declaring_deployment(name).each do |lib|
          @app.using_task_library(lib, location: location)
        end
        found = @app.orogen.find_deployment(name)
        return found if found

        raise DeploymentError.new(
          "no deployment named '#{name}'#{Naming.did_you_mean(name, @app.orogen.all_deployment_names)}",
          location: location,
          hint: "deployments are declared in .orogen files (deployment '#{name}' do task('name', 'lib::Task') end), " \
                "or made for one task with use_deployment OroGen.lib.Task => 'name'"
        )
      end

      def task_deployment(model, name, location)
        raise usage_error(model, location) unless model.is_a?(Class) && model <= Syskit::TaskContext && model.spec

        deployment = Orogen::DeploymentSpec.new(name.to_s, location: location)
        deployment.add_task(name.to_s, model, location: location)
        deployment
      end

      def usage_error(spec, location)
        DeploymentError.new(
          "use_deployment does not understand #{spec.inspect}",
          location: location,
          hint: "write use_deployment 'deployment_name' or use_deployment OroGen.lib.Task => 'task_name'"
        )
      end
    end
  end
end
