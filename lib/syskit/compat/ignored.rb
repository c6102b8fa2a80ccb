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

      def to_s
        '(not modelled)'
      end
      alias inspect to_s

      private

      def method_missing(_name, *_args, **_options, &)
        self
      end

      def respond_to_missing?(_name, _include_private = false)
        true
      end
    end
  end
end
