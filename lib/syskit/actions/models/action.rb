# frozen_string_literal: true

module Syskit
  module Actions
    module Models
      # What requirements are as an action of Syskit's action interface
      # (+InstanceRequirements#to_action_model+): the task model it
      # returns and an argument per argument of that model, required when
      # it has no default. A description: running the action is Roby's.
      class Action
        # An argument of the action: required, or with a default (nil for
        # a default read at runtime, +from(:parent_task)+).
        Argument = Struct.new(:name, :doc, :required, :default, keyword_init: true)

        attr_reader :requirements, :doc

        def initialize(requirements, doc = nil)
          @requirements = requirements
          @doc = doc || requirements.doc
          @arguments = Action.arguments_of(requirements).freeze
          freeze
        end

        # The arguments of the task model of +requirements+; those the
        # requirements set are optional, with the value set as default.
        def self.arguments_of(requirements)
          model = requirements.component_model
          return {} unless model.respond_to?(:model_argument_declarations)

          model.model_argument_declarations.to_h do |name, (default, _location, doc)|
            default = requirements.arguments.fetch(name, default)
            required = default.equal?(Syskit::Models::TaskArguments::NO_DEFAULT)
            default = nil if required || default.is_a?(Compat::DelayedArgument)
            [name, Argument.new(name: name, doc: doc, required: required, default: default)]
          end
        end

        def name
          requirements.name
        end

        # The model of the task the action gives.
        def returned_type
          requirements.proxy_model
        end

        def find_arg(name)
          @arguments[name.to_sym]
        end

        def has_arg?(name) # rubocop:disable Naming/PredicatePrefix -- Roby's name
          @arguments.key?(name.to_sym)
        end

        def each_arg(&)
          @arguments.each_value(&)
        end

        # The task of the requirements with +arguments+ (see
        # InstanceRequirements#instanciate), added to +plan+.
        def instanciate(plan, arguments = {})
          requirements.dup.with_arguments(**arguments).instanciate(plan)
        end

        def to_s
          "action of #{requirements}"
        end
      end
    end
  end
end
