# frozen_string_literal: true

module Syskit
  module Network
    # Step 3: binds every task to a deployed task of the robot configuration.
    # Among several candidates, the device's prefer_deployed_tasks chooses.
    # A device's deployed_as gives its driver a deployment of its own.
    class Deploy
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
          requirement = task.requirement
          declared = declared(task, requirement.device.declared_deployment) unless stub
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

        Orogen::DeploymentSpec.new(declaration.name, location: declaration.location, unmanaged: declaration.unmanaged)
                              .add_task(declaration.name, task.model, location: declaration.location)
      end

      # A deployed_as name and a deployed task of the robot configuration
      # of the same name are one process: they share a key.
      def declared_key(deployed)
        @config_tasks ||= @context.robot_config.deployed_tasks.to_h { |t| [t.name, t] }
        @declared_keys[deployed.name] ||= @config_tasks[deployed.name] || deployed
      end

      def stub_deployment(task)
        name = @context.device_of(task).name
        Orogen::DeploymentSpec.new("stub_#{name}").add_task(name, task.model)
      end

      def choose(task, requirement)
        index = @context.robot_config.candidates_for(task.model)
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

      # Candidates matching the hints: names are looked up, only regexps
      # are matched against every candidate of the model.
      def preferred(index, hints)
        found = hints.flat_map do |hint|
          hint.is_a?(Regexp) ? index.list.select { |c| hint.match?(c.name) } : [index.by_name[hint]].compact
        end
        found.size > 1 ? found.uniq.sort_by(&:name) : found
      end

      def device_location(requirement)
        requirement.device.declared_at
      end

      def none(task, requirement)
        device = requirement.device
        alternatives = library_deployments(task).map { |d| " or Syskit.conf.use_deployment '#{d}'" }.join
        DeploymentError.new(
          "no deployed task can run #{task.model.name}, the driver of #{device}, on #{@context.robot_config}",
          location: device_location(requirement),
          hint: "add to config/robots/#{@context.robot_config.name}.rb: " \
                "Syskit.conf.use_deployment OroGen.#{task.model.name.gsub('::', '.')} => '#{device.name}'" \
                "#{alternatives}"
        )
      end

      # The deployments that oroGen libraries declare for +task+'s model.
      def library_deployments(task)
        @context.app.orogen.each_task_model.select { |m| m <= task.model }.flat_map do |m|
          m.spec.library.deployments.values.select { |d| d.tasks.any? { |t| t.model <= task.model } }.map(&:name)
        end
      end

      def no_preferred(task, requirement, candidates)
        hints = requirement.deployment_hints.map(&:inspect).join(', ')
        DeploymentError.new(
          "no deployed task that can run the driver of #{requirement.device} (#{task.model.name}) " \
          "matches prefer_deployed_tasks(#{hints}): #{Naming.enumerate(candidates)}",
          location: requirement.device.deployment_hints_location || device_location(requirement),
          hint: 'change the pattern, or deploy a task whose name matches it'
        )
      end

      def several(task, requirement, candidates, index)
        name = requirement.device.name
        # A lookup: this error may be made for each of thousands of devices.
        found = index.by_name[name]
        named = found && (candidates.equal?(index.list) || candidates.include?(found))
        example = named ? "'#{name}'" : "/#{candidates.first.name}/"
        DeploymentError.new(
          "several deployed tasks can run the driver of #{requirement.device} (#{task.model.name}): " \
          "#{Naming.enumerate(candidates)}",
          location: device_location(requirement),
          hint: "choose one with .prefer_deployed_tasks(#{example}) on the device declaration"
        )
      end

      def shared(deployed, first_task, second_task)
        first = @context.device_of(first_task)
        second = @context.device_of(second_task)
        declared = second.declared_deployment
        hint = if declared
                 "give each device a deployed task of its own, e.g. deployed_as('#{second.name}')"
               else
                 'deploy one task per device (usually named after the device) and tell them apart ' \
                   "with .prefer_deployed_tasks(/#{second.name}/)"
               end
        DeploymentError.new(
          "#{first} and #{second} both need the deployed task #{deployed} " \
          "(#{first} is declared at #{first.declared_at})",
          location: declared&.location || second.declared_at, hint: hint
        )
      end
    end
  end
end
