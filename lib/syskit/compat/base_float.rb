# frozen_string_literal: true

module Syskit
  # Rock's Ruby helpers that the gem provides.
  module Compat
    # Rock's base/float (+require 'base/float'+): how Rock code writes
    # values that are not known or not set, as NaN. Installed as the
    # top-level +Base+ while an app is active.
    module BaseFloat
      module_function

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

    # Rock's Ruby libraries whose definitions the gem provides (see
    # BaseFloat): requiring one without Rock installed loads nothing more.
    PROVIDED_LIBRARIES = %w[base/float].freeze

    def self.provided_library?(name)
      PROVIDED_LIBRARIES.include?(name.to_s)
    end
  end
end
