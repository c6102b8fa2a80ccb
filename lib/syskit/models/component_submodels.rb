# frozen_string_literal: true

module Syskit
  module Models
    # The submodels of a component model, as MetaRuby keeps them for
    # Syskit's models: +has_submodel?+, +each_submodel+ and
    # +clear_submodels+ (which makes the model forget them, and them
    # theirs). Ruby's own Class#subclasses holds them, weakly, so that the
    # models of an unloaded app go; a forgotten submodel is only marked.
    module ComponentSubmodels
      # Enumerates the submodels made from this model, directly or not,
      # that it has not forgotten.
      def each_submodel(&block)
        return enum_for(__method__) unless block

        subclasses.each do |sub|
          next if sub.forgotten_by_parent?

          yield sub
          sub.each_submodel(&block)
        end
      end

      # Whether +model+ is one of this model's submodels (see #each_submodel).
      def has_submodel?(model) # rubocop:disable Naming/PredicatePrefix -- MetaRuby's name
        each_submodel.include?(model)
      end

      # The placeholder models made from this one, by kind and services
      # (see Placeholder.for): submodels too, made anew once forgotten.
      def placeholder_models
        @placeholder_models ||= {}
      end

      # Forgets the submodels of this model, and theirs.
      def clear_submodels
        @placeholder_models = nil
        subclasses.each do |sub|
          sub.clear_submodels
          next if ComponentSubmodels.permanent?(sub)

          sub.instance_variable_set(:@forgotten_by_parent, true)
          Models.remove_constant_of(sub)
        end
      end

      LIB_DIR = File.expand_path('../..', __dir__)

      # Whether +model+ is one of the gem's own (a constant its lib/ defines;
      # the constants of an unloaded app's models are gone).
      def self.permanent?(model)
        name = Module.instance_method(:name).bind_call(model)
        file, = Object.const_source_location(name) if name
        file&.start_with?(LIB_DIR) || false
      rescue NameError
        false
      end

      # Whether its parent model forgot it (see #clear_submodels).
      def forgotten_by_parent?
        @forgotten_by_parent == true
      end
    end
  end
end
