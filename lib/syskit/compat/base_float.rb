# frozen_string_literal: true

module Syskit
  # Rock's Ruby helpers that the gem provides.
  module Compat
    # Rock's base/float (+require 'base/float'+): how Rock code writes
    # values that are not known or not set, as NaN. The top-level +Base+
    # once a file requires it (a +Base+ module the app's files already
    # define gains these methods, as Ruby reopens it in Rock).
    module BaseFloat
      extend self # rubocop:disable Style/ModuleFunction -- public methods, for Base.extend(BaseFloat)

      def unset
        Float::NAN
      end

      def unknown
        Float::NAN
      end

      def unset?(value)
        value.respond_to?(:nan?) && value.nan?
      end

      def unknown?(value)
        unset?(value)
      end

      def infinity
        Float::INFINITY
      end

      def infinity?(value)
        value.respond_to?(:infinite?) && !value.infinite?.nil?
      end
    end

    # Rock's Ruby libraries whose definitions the gem provides, with the
    # top-level constant each defines: requiring one without Rock installed
    # installs that constant (removed with the app, as what its files
    # define), and loads nothing more.
    PROVIDED_LIBRARIES = { 'base/float' => [:Base, BaseFloat] }.freeze

    def self.provided_library?(name)
      PROVIDED_LIBRARIES.key?(name.to_s)
    end

    # Requires the provided library +name+: true the first time, as
    # Kernel#require.
    def self.require_provided(name)
      constant, methods = PROVIDED_LIBRARIES.fetch(name.to_s)
      if Object.const_defined?(constant, false)
        existing = Object.const_get(constant)
        return false if existing.singleton_class.include?(methods)

        existing.extend(methods)
      else
        # A module of the app's own, which its files may reopen.
        Object.const_set(constant, Module.new.extend(methods))
      end
      true
    end
  end
end
