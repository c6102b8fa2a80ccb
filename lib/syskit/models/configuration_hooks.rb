# frozen_string_literal: true

module Syskit
  module Models
    # Which of Syskit's two configuration hooks a task model uses (see
    # #use_update_properties?). The generator asks for every task it
    # configures, so the answer is kept per model, and computed again once
    # any task model defined or removed one of the hooks (a model file
    # loaded later, a test's class_eval; the answer of a model depends on
    # its parents too): those count as declarations that changed (see
    # Component#cached).
    module ConfigurationHooks
      HOOKS = %i[update_properties configure].freeze

      # Whether the task is configured through +update_properties+ (Syskit's
      # newer hook) rather than +configure+: true unless a model class below
      # Syskit::TaskContext defines +configure+ and none defines
      # +update_properties+. Methods of modules mixed in are not counted.
      def use_update_properties?
        cached(:use_update_properties) { compute_use_update_properties }
      end

      # Ruby's hooks, called on the class a method is defined in.
      def method_added(name)
        super
        Component.declarations_changed if HOOKS.include?(name)
      end

      def method_removed(name)
        super
        Component.declarations_changed if HOOKS.include?(name)
      end

      def method_undefined(name)
        super
        Component.declarations_changed if HOOKS.include?(name)
      end

      private

      def compute_use_update_properties
        configure = false
        ancestors.each do |klass|
          break if klass.equal?(Syskit::TaskContext)
          next unless klass.is_a?(Class)
          return true if defines_own?(klass, :update_properties)

          configure ||= defines_own?(klass, :configure)
        end
        !configure
      end

      def defines_own?(klass, name)
        klass.method_defined?(name, false) || klass.private_method_defined?(name, false)
      end
    end
  end
end
