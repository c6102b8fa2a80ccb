# frozen_string_literal: true

module Syskit
  module Models
    # The MetaRuby model API that service, device and bus models have in
    # Syskit, which bundles' custom model classes use: +new_submodel+,
    # +supermodel+ (the model a submodel was made from), +each_submodel+,
    # and +root+. Part of DataServiceModel.
    #
    # A custom model class may define an +initialize+ of its own without
    # arguments, as MetaRuby allows (+def initialize; super; self.root =
    # true; self.supermodel = nil; provides Syskit::DataService; end+).
    module ModelHierarchy
      # The model this one was made from (+Parent.new_submodel+, or the
      # +parent:+ of its declaration), or nil for a root.
      attr_accessor :supermodel

      # MetaRuby's mark of the root of a hierarchy of models; recorded.
      attr_accessor :root

      # Methods of the model classes.
      module ClassMethods
        # A new model of this class, declared at +location+, named +name+
        # until a constant names it.
        def build(location:, name: nil)
          model = if takes_identity?
                    new(location: location, name: name)
                  else
                    new.tap { |m| m.send(:identify, location, name) }
                  end
          Models.register_model(model)
          model
        end

        # The roots declared by the gem (Syskit::DataService, ...), which
        # every app's models are submodels of: what an app registered on
        # them goes when it is unloaded.
        def forget_submodels_of_roots
          [Syskit::DataService, Syskit::Device, Syskit::ComBus].each { |root| root.send(:forget_submodels) }
        end

        private

        def takes_identity?
          instance_method(:initialize).parameters.any? { |kind, name| kind == :keyrest || name == :location }
        end
      end

      def self.included(base)
        base.extend(ClassMethods)
      end

      # A new model of this one's class that provides this one, as Syskit's
      # +Device.new_submodel(name: 'Camera') { output_port ... }+: for
      # models made in Ruby rather than with a statement (tests, stubs,
      # bundles' model helpers).
      def new_submodel(name: nil, **options, &block)
        self.class.build(location: Location.of_caller, name: name).send(:declare, self, options, block)
      end

      # Enumerates the models made from this one, directly or not, in the
      # order they were made.
      def each_submodel(&block)
        return enum_for(__method__) unless block

        (@submodels || []).each(&block)
      end

      # Whether +model+ was made from this one, directly or not.
      def has_submodel?(model) # rubocop:disable Naming/PredicatePrefix -- MetaRuby's name
        each_submodel.include?(model)
      end

      protected

      def register_submodel(model)
        (@submodels ||= []) << model
        supermodel&.register_submodel(model)
      end

      private

      def identify(location, name)
        @declared_at = location
        @given_name = name
      end

      def forget_submodels
        @submodels = nil
      end

      # Records that this model was made from +parent+.
      def made_from(parent)
        return if equal?(parent)

        self.supermodel = parent
        parent.register_submodel(self)
      end
    end
  end
end
