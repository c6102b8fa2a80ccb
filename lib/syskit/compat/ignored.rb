# frozen_string_literal: true

module Syskit
  module Compat
    # What a statement of a construct this gem does not model returns
    # (+add(Srv, as: 'x')+ in a composition, +describe('...')+ in an action
    # interface): it takes any chained call (+.with_arguments(...)+,
    # +.command_port.connect_to ...+) and returns itself, so that the file
    # goes on loading. Syskit's own models never return one.
    class Ignored < BasicObject
      def self.instance
        @instance ||= new
      end

      # +what+: what the statement made, for the warnings of what
      # depends on it ("the device of use_gazebo_model 'model://ur10'").
      def initialize(what = nil)
        @what = what
      end

      def to_s
        @what || '(not modelled)'
      end
      alias inspect to_s

      # It may be a hash key (+specialize child => Srv+).
      def hash
        __id__
      end

      def eql?(other)
        equal?(other)
      end

      # Ruby's implicit conversions (to_ary, to_str, ...) are not taken:
      # Ruby then treats the object as what it is, not as an array.
      CONVERSIONS = %i[to_ary to_str to_hash to_proc to_int to_io to_regexp to_sym to_path to_a to_h].freeze

      private

      def method_missing(name, *_args, **_options, &)
        return super if CONVERSIONS.include?(name)

        self
      end

      def respond_to_missing?(name, _include_private = false)
        !CONVERSIONS.include?(name)
      end
    end
  end
end
