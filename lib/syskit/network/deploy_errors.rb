# frozen_string_literal: true

module Syskit
  module Network
    # The errors of Deploy: what cannot be deployed, and how to fix it.
    # A task is either the driver of a device (the fix goes on the device
    # declaration) or a task a composition needs (on the child or the
    # definition).
    module DeployErrors
      private

      # Where to fix a task's deployment: its device's declaration, or the
      # definition its composition was made for.
      def device_location(requirement, task = nil)
        requirement.device&.declared_at || task&.root_location || requirement.declared_at
      end

      # What a task is, in messages.
      def what(task, requirement)
        device = requirement.device
        return "the driver of #{device} (#{task.model.name})" if device

        "#{task.plan_path || task.plan_name} (#{task.model.name})"
      end

      # How to prefer +name+ for +task+: on its device, or in the
      # definition, by the child's path below it.
      def prefer(task, requirement, name)
        return "choose one with .prefer_deployed_tasks(#{name}) on the device declaration" if requirement.device

        root, child = task.plan_path.to_s.split('.', 2)
        return "choose one with .prefer_deployed_tasks(#{name}) on the requirements" unless child

        "choose one in the definition of #{root}: .use('#{child}' => " \
          "#{Naming.dsl_reference(task.model)}.prefer_deployed_tasks(#{name}))"
      end

      def none(task, requirement)
        name = requirement.device&.name || task.plan_name
        alternatives = library_deployments(task).map { |d| " or Syskit.conf.use_deployment '#{d}'" }.join
        error = DeploymentError.new(
          "no deployed task can run #{task.model.name}, " \
          "#{requirement.device ? "the driver of #{requirement.device}" : "needed by #{task.plan_path}"}, " \
          "on #{@context.robot_config}",
          location: device_location(requirement, task),
          hint: "add to config/robots/#{@context.robot_config.name}.rb: " \
                "#{deploy_statement(task.model, name)}#{alternatives}"
        )
        error.task = task
        error
      end

      # The deployments that oroGen libraries declare for +task+'s model
      # (for a specialization, the task model it specializes).
      def library_deployments(task)
        model = task.model.concrete_model
        @context.app.orogen.each_task_model.select { |m| m <= model }.flat_map do |m|
          m.spec.library.deployments.values.select { |d| d.task_activities.any? { |t| t.model <= model } }.map(&:name)
        end
      end

      def no_preferred(task, requirement, candidates)
        hints = requirement.deployment_hints.map(&:inspect).join(', ')
        DeploymentError.new(
          "no deployed task that can run #{what(task, requirement)} " \
          "matches prefer_deployed_tasks(#{hints}): #{Naming.enumerate(candidates)}",
          location: requirement.deployment_hints_location || device_location(requirement),
          hint: 'change the pattern, or deploy a task whose name matches it'
        )
      end

      def several(task, requirement, candidates, index)
        name = requirement.device&.name || task.plan_name
        # A lookup: this error may be made for each of thousands of devices.
        found = index.by_name[name]
        named = found && (candidates.equal?(index.list) || candidates.include?(found))
        example = "'#{named ? name : candidates.first.name}'"
        DeploymentError.new(
          "several deployed tasks can run #{what(task, requirement)}: #{Naming.enumerate(candidates)}",
          location: device_location(requirement, task),
          hint: prefer(task, requirement, example)
        )
      end

      def shared(deployed, first_task, second_task)
        first = first_task.requirements
        second = second_task.requirements
        DeploymentError.new(
          "#{describe(first_task)} and #{describe(second_task)} both need the deployed task #{deployed} " \
          "(#{describe(first_task)} is declared at #{device_location(first, first_task)})",
          location: second.declared_deployment&.location || device_location(second, second_task),
          hint: shared_hint(second_task, second)
        )
      end

      def shared_hint(task, requirement)
        name = task.plan_name
        if requirement.declared_deployment
          "give each #{requirement.device ? 'device' : 'task'} a deployed task of its own, e.g. deployed_as('#{name}')"
        elsif requirement.device
          'deploy one task per device (usually named after the device) and tell them apart ' \
            "with .prefer_deployed_tasks(/#{name}/)"
        else
          "deploy another one (#{deploy_statement(task.model, name)}) and " \
            "#{prefer(task, requirement, "'#{name}'").sub(/\Achoose one/, 'choose it')}"
        end
      end

      # The statement of a robot configuration deploying a task of +model+
      # as +name+ (a specialization runs on a deployment of its task model).
      def deploy_statement(model, name)
        model = model.concrete_model
        method = model <= RubyTaskContext ? 'use_ruby_tasks' : 'use_deployment'
        "Syskit.conf.#{method} #{Naming.dsl_reference(model)} => '#{name}'"
      end

      def describe(task)
        task.requirements.device&.to_s || task.plan_path || task.plan_name
      end
    end
  end
end
