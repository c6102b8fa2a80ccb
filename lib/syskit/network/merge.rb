# frozen_string_literal: true

require 'syskit/network/kept_tasks'

module Syskit
  module Network
    # Step 2: equal tasks made for different children become one, as
    # Syskit's merge solver does. Two tasks are equal when they have the
    # same model, arguments, sections and deployment hints (see
    # Instantiate.merge_key) and every input port they both have connected
    # is fed by the same ports (unless it multiplexes): two filters reading
    # two different sensors stay two tasks, two reading the same sensor
    # become one. Merging goes on until nothing more merges, since a merge
    # can make the inputs of the tasks downstream the same.
    #
    # Devices' drivers are one task per device from the start.
    class Merge
      def initialize(context)
        @context = context
      end

      def run
        groups = equal_groups(@context.tasks.reject { |t| t.requirements.device })
        return if groups.empty?

        replaced = {}.compare_by_identity
        loop do
          inputs = input_sources(replaced, groups)
          break if groups.sum { |group| merge_group(group, inputs, replaced) }.zero?

          groups = groups.map { |g| g.reject { |t| replaced.key?(t) } }.select { |g| g.size > 1 }
        end
        apply(replaced) unless replaced.empty?
      end

      private

      # Tasks with the same merge key, by groups of two or more.
      def equal_groups(tasks)
        tasks.group_by { |t| Instantiate.merge_key(t.model, t.requirements, t.arguments) }
             .values.select { |g| g.size > 1 }
      end

      # For each task of +groups+, its input ports' sources ([task, port]
      # pairs), tasks already merged standing for the ones they replaced.
      # Connections into other tasks are not resolved: most tasks of a
      # large network merge with none.
      def input_sources(replaced, groups)
        wanted = {}.compare_by_identity
        groups.each { |group| group.each { |task| wanted[task] = true } }
        sources = Hash.new { |h, task| h[task] = Hash.new { |ports, name| ports[name] = [] } }.compare_by_identity
        @context.compositions.each do |composition|
          composition.model.port_connections.each do |connection|
            into = composition.children_by_role[connection.to.child_name]
            next unless into.is_a?(Composition) || wanted.key?(final(into, replaced))

            add_source(sources, composition, connection, replaced)
          end
        end
        sources
      end

      def add_source(sources, composition, connection, replaced)
        from = composition.resolve_child_port(connection.from)
        to = composition.resolve_child_port(connection.to)
        return unless from && to

        source = [final(from[0], replaced).object_id, from[1]]
        list = sources[final(to[0], replaced)][to[1]]
        list << source unless list.include?(source)
      end

      def final(task, replaced)
        task = replaced[task] while replaced.key?(task)
        task
      end

      # Merges what can be merged in +group+; returns how many tasks went.
      # Each task merges into the first task kept before it whose inputs
      # agree with its own (see #inputs), found through hashes (see
      # KeptTasks) rather than by comparing it with every kept task: a
      # group holds thousands of tasks when compositions differ only by
      # what feeds them.
      def merge_group(group, inputs, replaced)
        kept = KeptTasks.new
        group.each do |task|
          signature = inputs(task, inputs)
          target = kept.first_agreeing(signature)
          target ? merge_into(target, task, replaced) : kept.add(task, signature)
        end
        group.size - kept.size
      end

      # +task+ goes, +target+ stands for it: it may use the deployments of
      # +task+'s requirements too (as Syskit merges deployment groups).
      def merge_into(target, task, replaced)
        replaced[task] = target
        group = task.requirements.deployment_group
        return if group.empty? || group.equal?(target.requirements.deployment_group)

        target.requirements = target.requirements.dup.use_deployment_group(group)
      end

      # The connected input ports of +task+ that do not multiplex, with
      # their sources, sorted. Two tasks' inputs agree when every port both
      # have is fed by the same sources (a multiplexing port takes any).
      def inputs(task, inputs)
        inputs.fetch(task, {}).each_with_object({}) do |(port, sources), signature|
          signature[port] = sources.sort unless task.find_orogen_port(port)&.multiplexes?
        end
      end

      def apply(replaced)
        @context.tasks.reject! { |t| replaced.key?(t) }
        @context.compositions.each do |composition|
          composition.children_by_role.each do |role, task|
            composition.add_child(role, final(task, replaced)) if replaced.key?(task)
          end
        end
        @context.roots.map! { |t| replaced.key?(t) ? final(t, replaced) : t }
      end
    end
  end
end
