# frozen_string_literal: true

module Syskit
  module Models
    class CompositionChild
      # How a child of a composition model finds what stands for it among
      # the tasks of a plan, as Syskit's CompositionChild does: the child
      # task of a composition task (through the service the child
      # requires), and the reverse, a task bound to the child it is. Part
      # of CompositionChild.
      module Binding
        # What stands for this child in +composition+ (a task of
        # #composition_model): its child task of this role, or that task's
        # service the child requires; nil when it has none.
        def try_resolve_and_bind_child(composition)
          composition.find_required_composition_child_from_role(child_name, composition_model)
        end

        # As #try_resolve_and_bind_child, an ArgumentError when there is none.
        def resolve_and_bind_child(composition)
          try_resolve_and_bind_child(composition) ||
            raise(ArgumentError, "#{composition} has no child '#{child_name}' standing for #{self}")
        end

        # What stands for this child under +root+, a task of the outermost
        # composition model: through the child compositions this child is
        # reached through (+first_child.second_child+).
        def try_resolve_and_bind_child_recursive(root)
          parent = reached_through ? reached_through.try_resolve_and_bind_child_recursive(root) : root
          parent = parent.component if parent.is_a?(Syskit::BoundDataService)
          parent && try_resolve_and_bind_child(parent)
        end

        # As #try_resolve_and_bind_child_recursive, an ArgumentError when
        # there is none.
        def resolve_and_bind_child_recursive(root)
          try_resolve_and_bind_child_recursive(root) ||
            raise(ArgumentError, "#{root} has no task standing for #{self}")
        end

        # +object+ (a task, or a task's service) as this child: a service
        # is kept when it provides what the child requires; a task must be
        # the child of this role of a composition of #composition_model.
        def bind(object)
          return bind_service(object) if object.is_a?(Syskit::BoundDataService)

          parents = object.each_parent_task.select { |parent| parent.model.fullfills?(composition_model) }
          if parents.empty?
            raise ArgumentError, "cannot bind #{self}[#{model}] to #{identity(object)}: it is not the child of any " \
                                 "#{composition_model} composition"
          end

          parent = parents.find { |p| p.find_child_from_role(child_name).equal?(object) }
          return parent.find_required_composition_child_from_role(child_name, composition_model) if parent

          raise ArgumentError, "cannot bind #{self}[#{model}] to #{identity(object)}: it is the child of one or more " \
                               "#{composition_model} compositions, but not with the role '#{child_name}'"
        end

        private

        def bind_service(service)
          required = models.grep(DataServiceModel)
          return service if required.all? { |m| service.fullfills?(m) }

          bound = "#<BoundDataService: #{identity(service.component)}.#{service.name}>"
          raise ArgumentError, "cannot bind #{model} to #{bound}"
        end

        # A task as Syskit's messages name it: its model and its identity
        # (+task_m:0x5640+), there may be several tasks of one model.
        def identity(task)
          "#{task.model}:0x#{task.object_id.to_s(16)}"
        end
      end
    end
  end
end
