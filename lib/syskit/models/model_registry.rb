# frozen_string_literal: true

module Syskit
  # What the app's model files define (see Models.defined_models).
  module Models
    # Models in the order they were defined, so that tests can remove the
    # ones they made (see Test::ModelHelpers).
    def self.defined_models
      @defined_models ||= []
    end

    def self.register_model(model)
      defined_models << model
    end

    # Removes the constants naming the models defined after the first
    # +mark+ ones, and forgets them.
    def self.clear_defined_since(mark)
      (defined_models.slice!(mark..) || []).reverse_each { |model| remove_constant_of(model) }
    end

    # Removes the constant naming +model+ (+A::B::Model+), if it names it.
    def self.remove_constant_of(model)
      name = model.name
      return unless name.is_a?(String) && name.match?(/\A[A-Z]\w*(::[A-Z]\w*)+\z/)

      parent, _, base = name.rpartition('::')
      namespace = Object.const_get(parent) if Object.const_defined?(parent)
      namespace.send(:remove_const, base) if namespace&.const_defined?(base, false) &&
                                             namespace.const_get(base, false).equal?(model)
    end
  end
end
