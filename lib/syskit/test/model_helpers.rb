# frozen_string_literal: true

module Syskit
  module Test
    # What Syskit's tests call to make models of their own: types that
    # exist only for the test, and the removal of the models a test
    # defined (so that the next test can define them again).
    module ModelHelpers
      # A type for the test (+stub_type '/Command'+): an opaque type of
      # that name, or the app's own when it has one.
      def stub_type(name)
        types = Test.app.types
        types.find(name) || types.register(Types::OpaqueType.new(Types::Registry.normalize(name)))
      end

      # Removes the constants of the models defined since the test started
      # (services, devices, compositions made in the test or by helpers
      # it called), as Syskit's +clear_newly_defined_models+.
      def clear_newly_defined_models
        Models.clear_defined_since(@syskit_models_mark || 0)
      end

      def before_setup
        super
        @syskit_models_mark = Models.defined_models.size
      end
    end
  end
end
