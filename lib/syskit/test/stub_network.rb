# frozen_string_literal: true

module Syskit
  module Test
    # Syskit's network stubbing on tasks already in the test's plan
    # (+Cmp.instanciate(plan)+): each abstract task is replaced by a task
    # of a stub model providing the same services (see StubModels), in
    # the plan and in the compositions it is a child of. Plan services
    # (+task.as_service+) follow the replacements.
    #
    #   stubs = StubNetwork.new(self)
    #   cmp = stubs.apply([Cmp.instanciate(plan)]).first
    #   cmp.srv_child.abstract? # => false
    class StubNetwork
      # +test+ gives the plan (+test.plan+).
      def initialize(test)
        @plan = test.plan
      end

      # Stubs the networks of +root_tasks+ and returns, for each root, the
      # task that stands for it afterwards (itself unless it was abstract).
      def apply(root_tasks)
        replacements = {}.compare_by_identity
        root_tasks.map { |task| stub(task, replacements) }
      end

      private

      def stub(task, replacements)
        return replacements[task] if replacements.key?(task)

        replacement = task.abstract? ? concrete_task(task) : task
        replacements[task] = replacement
        @plan.replace_task(task, replacement) unless replacement.equal?(task)
        if replacement.is_a?(Composition)
          replacement.children_by_role.to_a.each do |role, child|
            stubbed = stub(child, replacements)
            replacement.add_child(role, stubbed) unless stubbed.equal?(child)
          end
        end
        replacement
      end

      # A task of a stub model standing for abstract +task+.
      def concrete_task(task)
        model = task.model
        stub_model =
          if model.placeholder?
            base = model.proxied_component_model
            base = nil if base.equal?(Syskit::Component) || base.equal?(Syskit::TaskContext)
            Network::StubModels.service_provider(model.proxied_data_service_models, base: base)
          else
            Network::StubModels.service_provider([], base: model)
          end
        stub_model.new(task.arguments.to_h)
      end
    end
  end
end
