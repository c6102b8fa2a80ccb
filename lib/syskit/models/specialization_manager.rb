# frozen_string_literal: true

module Syskit
  module Models
    # The specializations of a composition model, its parents' included, as
    # Syskit's +Cmp.specializations+ gives them: each CompositionSpecialization
    # in declaration order (Enumerable), and +specializations+, the same by
    # what they specialize (child name => models).
    class SpecializationManager
      include Enumerable

      attr_reader :composition_model

      def initialize(composition_model, specializations)
        @composition_model = composition_model
        @list = specializations.freeze
      end

      # The specializations by what they specialize (child name => models).
      def specializations
        @list.to_h { |spec| [spec.specialized_children, spec] }
      end

      def each_specialization(&)
        return enum_for(__method__) unless block_given?

        @list.each(&)
      end
      alias each each_specialization

      def empty?
        @list.empty?
      end

      def size
        @list.size
      end

      def to_s
        "specializations of #{composition_model}"
      end
      alias inspect to_s
    end
  end
end
