# frozen_string_literal: true

require 'syskit/network/deploy_errors'

module Syskit
  module Network
    # Step 3: binds every task to a deployed task of the robot configuration.
    # Among several candidates, the device's prefer_deployed_tasks chooses.
    # A device's deployed_as gives its driver a deployment of its own.
    class Deploy
      include DeployErrors

      def initialize(context)
        @context = context
        # What stands for a deployed_as name when telling deployed tasks
        # apart: the robot configuration's task of that name, else the
        # first deployed task made under it.
        @declared_keys = {}
      end

      def run
        used = {}.compare_by_identity
        stub = @context.stub_deployments
        @context.tasks.each do |task|
          # Only task contexts run in a deployment (a plain
          # Syskit::Component has none, as in Syskit).
          next unless task.is_a?(TaskContext)

          requirement = task.requirements
          declared = declared(task, requirement.declared_deployment) unless stub
          deployed = declared || (stub ? stub_deployment(task) : choose(task, requirement))
          next unless deployed

          key = declared ? declared_key(declared) : deployed
          if (other = used[key])
            @context.error(shared(deployed, other, task))
          else
            used[key] = task
            task.deployed_task = deployed
          end
        end
      end

      private

      # The deployed task of the device's deployed_as (+declaration+), if any.
      def declared(task, declaration)
        return unless declaration

        Orogen::DeploymentSpec.new(declaration.name, declaration.location, unmanaged: declaration.unmanaged)
                              .add_task(declaration.name, task.model, location: declaration.location)
      end

      # A deployed_as name and a deployed task of the robot configuration
      # of the same name are one process: they share a key.
      def declared_key(deployed)
        @config_tasks ||= @context.robot_config.deployed_tasks.to_h { |t| [t.name, t] }
        @declared_keys[deployed.name] ||= @config_tasks[deployed.name] || deployed
      end

      def stub_deployment(task)
        name = task.plan_name
        Orogen::DeploymentSpec.new("stub_#{name}").add_task(name, task.model)
      end

      def choose(task, requirement)
        index = candidates(task, task.model.concrete_model)
        return @context.error(none(task, requirement)) if index.empty?

        hints = requirement.deployment_hints
        # The common case, a deployed task named after the device: a lookup.
        if hints.size == 1 && hints.first.is_a?(String)
          return index.by_name[hints.first] || @context.error(no_preferred(task, requirement, index.list))
        end

        candidates = index.list
        unless hints.empty?
          preferred = preferred(index, hints)
          return @context.error(no_preferred(task, requirement, candidates)) if preferred.empty?

          candidates = preferred
        end
        return candidates.first if candidates.size == 1

        @context.error(several(task, requirement, candidates, index))
      end

      # The deployed tasks that may run +task+ as a task of +model+, as
      # Syskit chooses them: those of the deployment group of the task's
      # requirements (with their profile's), else those of its parents'
      # (each up to its root), else the robot configuration's.
      def candidates(task, model)
        return @context.robot_config.candidates_for(model) unless groups?

        own = group_of(task.requirements)&.candidates_for(model)
        return own if own && !own.empty?

        parents = task.each_parent_task.to_a
        return @context.robot_config.candidates_for(model) if parents.empty?

        found = parents.map { |parent| candidates(parent, model) }.uniq
        found.size == 1 ? found.first : Models::DeploymentGroup::Candidates.new(found.map(&:list))
      end

      # Whether a requirement of the network or its profile has a
      # deployment group: most networks deploy from the robot only.
      def groups?
        return @groups if defined?(@groups)

        @groups = (@context.tasks + @context.compositions).any? { |t| group_of(t.requirements) }
      end

      # The deployment group of +requirements+ and of their profile, nil
      # when both are empty.
      def group_of(requirements)
        return unless requirements

        (@groups_of ||= {}.compare_by_identity).fetch(requirements) do
          own = requirements.deployment_group
          profile = requirements.profile
          profile_group = profile.deployment_group if profile.respond_to?(:deployment_group)
          group = own.empty? ? nil : own
          unless profile_group.nil? || profile_group.empty?
            group = (group&.dup || Models::DeploymentGroup.new).use_group(profile_group)
          end
          @groups_of[requirements] = group
        end
      end

      # Candidates matching the hints: names are looked up, only regexps
      # are matched against every candidate of the model.
      def preferred(index, hints)
        found = hints.flat_map do |hint|
          next [index.by_name[hint]].compact if hint.is_a?(String)

          index.list.select { |c| hint === c.name } # rubocop:disable Style/CaseEquality -- Syskit's matching
        end
        found.size > 1 ? found.uniq.sort_by(&:name) : found
      end
    end
  end
end
