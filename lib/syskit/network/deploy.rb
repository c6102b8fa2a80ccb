# frozen_string_literal: true

module Syskit
  module Network
    # Step 3: binds every task to a deployed task of the robot configuration.
    # Among several candidates, the device's prefer_deployed_tasks chooses.
    class Deploy
      def initialize(context)
        @context = context
      end

      def run
        used = {}.compare_by_identity
        @context.tasks.each do |task|
          deployed = @context.stub_deployments ? stub_deployment(task) : choose(task)
          next unless deployed

          if (other = used[deployed])
            @context.error(shared(deployed, other, task))
          else
            used[deployed] = task
            task.deployed_task = deployed
          end
        end
      end

      private

      def stub_deployment(task)
        name = @context.device_of(task).name
        Orogen::DeploymentSpec.new("stub_#{name}").add_task(name, task.model)
      end

      def choose(task)
        requirement = @context.requirement_for(task)
        candidates = @context.robot_config.deployed_tasks_for(task.model).sort_by(&:name)
        return @context.error(none(task, requirement)) if candidates.empty?

        hints = requirement.deployment_hints
        unless hints.empty?
          preferred = candidates.select { |c| hints.any? { |h| h.is_a?(Regexp) ? h.match?(c.name) : h == c.name } }
          return @context.error(no_preferred(task, requirement, candidates)) if preferred.empty?

          candidates = preferred
        end
        return candidates.first if candidates.size == 1

        @context.error(several(task, requirement, candidates))
      end

      def device_location(requirement)
        requirement.device.declared_at
      end

      def none(task, requirement)
        device = requirement.device
        in_libraries = @context.app.orogen.each_task_model.select { |m| m <= task.model }.flat_map do |m|
          m.spec.library.deployments.values.select { |d| d.tasks.any? { |t| t.model <= task.model } }.map(&:name)
        end
        alternatives = in_libraries.map { |d| " or Syskit.conf.use_deployment '#{d}'" }.join
        DeploymentError.new(
          "no deployed task can run #{task.model.name}, the driver of #{device}, on #{@context.robot_config}",
          location: device_location(requirement),
          hint: "add to config/robots/#{@context.robot_config.name}.rb: " \
                "Syskit.conf.use_deployment OroGen.#{task.model.name.gsub('::', '.')} => '#{device.name}'#{alternatives}"
        )
      end

      def no_preferred(task, requirement, candidates)
        hints = requirement.deployment_hints.map(&:inspect).join(', ')
        DeploymentError.new(
          "none of the deployed tasks that can run #{requirement.device}'s driver #{task.model.name} " \
          "matches prefer_deployed_tasks(#{hints}): #{candidates.map(&:to_s).join(', ')}",
          location: device_location(requirement),
          hint: 'change the pattern, or deploy a task whose name matches it'
        )
      end

      def several(task, requirement, candidates)
        DeploymentError.new(
          "several deployed tasks can run #{requirement.device}'s driver #{task.model.name}: " \
          "#{candidates.map(&:to_s).join(', ')}",
          location: device_location(requirement),
          hint: "choose one with .prefer_deployed_tasks(/#{candidates.first.name}/) on the device declaration"
        )
      end

      def shared(deployed, first_task, second_task)
        first = @context.device_of(first_task)
        second = @context.device_of(second_task)
        DeploymentError.new(
          "#{first} and #{second} both need the deployed task #{deployed} " \
          "(#{first} is declared at #{first.declared_at})",
          location: second.declared_at,
          hint: 'deploy one task per device (usually named after the device) and tell them apart ' \
                "with .prefer_deployed_tasks(/#{second.name}/)"
        )
      end
    end
  end
end
