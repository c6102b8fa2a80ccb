# frozen_string_literal: true

module Syskit
  class InstanceRequirements
    # How requirements change, as Syskit's: a statement changes the
    # requirements it is called on and returns them, unless they are held
    # (frozen: what a model, a profile or an injection was given; or a
    # profile's device action), when it returns a changed copy. +dup+
    # gives a copy to change. Part of InstanceRequirements.
    module Changes
      # A copy to change (Syskit's +dup+): its statements change it, and
      # its deployment hints and group are its own.
      def initialize_copy(other)
        super
        @open = false
        @deployment_hints = @deployment_hints.dup
        @deployment_group = @deployment_group&.dup
        extend_readers
      end

      # Frozen with their deployment hints and group: requirements a model
      # or a profile holds are not changed through them.
      def freeze
        freeze_deployments
        super
      end

      # Whether statements give a changed copy rather than changing these
      # requirements: frozen ones (what models, profiles and injections
      # hold), and a profile's device actions.
      def held?
        frozen? || @open
      end

      # The same requirements on +models+, without a selected service or task.
      def with_models(models)
        copy(models: models, service: nil, instance: nil)
      end

      private

      # New requirements with +changes+ (FIELDS values, and +class:+),
      # frozen when these are held.
      def copy(**changes)
        values = FIELDS.to_h { |f| [f, instance_variable_get(:"@#{f}")] }
        values[:selections] ||= DependencyInjection::EMPTY
        values[:arguments] ||= NO_ARGUMENTS
        values[:specialization_hints] ||= NO_HINTS
        own_models = values.delete(:models)
        models = changes.delete(:models) { own_models }
        made = changes.delete(:class) { self.class }.new(models, **values, **changes)
        held? ? made.freeze : made
      end

      # What a statement does: changes these requirements and returns them,
      # as Syskit's statements do, or returns a changed copy when they are
      # held (see #held?).
      def change(**changes)
        return copy(**changes) if held?

        changes.each do |field, value|
          value = value.dup.freeze if !value.frozen? && %i[arguments models conf].include?(field)
          value = value.dup if field == :deployment_hints
          instance_variable_set(:"@#{field}", value)
        end
        extend_readers
        self
      end

      def freeze_deployments
        @deployment_hints.freeze
        @deployment_group&.freeze
      end

      def extend_readers
        readers = Readers.for(component_model)
        extend(readers) if readers && !is_a?(readers)
      end
    end
  end
end
