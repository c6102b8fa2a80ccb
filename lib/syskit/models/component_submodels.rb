# frozen_string_literal: true

module Syskit
  module Models
    # The registry of the submodels of component models, as MetaRuby
    # keeps it for Syskit: each model knows the models made from it
    # (subclasses, at any depth: +Syskit::Component.has_submodel?(Cmp)+),
    # and +clear_submodels+ forgets them (Syskit's harness does between
    # tests). Part of Component.
    module ComponentSubmodels
      def inherited(submodel)
        super
        (@submodels ||= []) << submodel
      end

      # Enumerates the models made from this one, directly or not.
      def each_submodel(&block)
        return enum_for(__method__) unless block

        (@submodels || []).each do |submodel|
          yield submodel
          submodel.each_submodel(&block)
        end
      end

      # Whether +model+ was made from this one, directly or not.
      def has_submodel?(model) # rubocop:disable Naming/PredicatePrefix -- MetaRuby's name
        each_submodel.any? { |m| m.equal?(model) }
      end

      # Forgets the models made from this one, at any depth.
      def clear_submodels
        (@submodels || []).each(&:clear_submodels)
        @submodels = nil
      end
    end
  end
end
