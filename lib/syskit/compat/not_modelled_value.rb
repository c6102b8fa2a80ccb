# frozen_string_literal: true

module Syskit
  module Compat
    # An instance of a class this gem does not model, or what a call on
    # one returns: +Eigen::Vector3.new(1, 2, 3)+, +Eigen::Vector3.UnitZ+,
    # +q * Eigen::Quaternion.Identity+. It is the expression that made it,
    # so two values made alike are equal (+assert_equal+ on them compares
    # something) and a value of another expression is not; any call on it
    # is accepted and makes a new value.
    class NotModelledValue
      # +receiver+: the class or value the call was made on; +call+: its
      # name (:new for an instance); +arguments+: what it was given.
      def self.of(receiver, call, arguments)
        value = allocate
        value.instance_variable_set(:@expression, [receiver, call, arguments.freeze].freeze)
        value
      end

      def initialize(*arguments, **options)
        @expression = [self.class, :new, (options.empty? ? arguments : [*arguments, options]).freeze].freeze
      end

      def ==(other)
        other.is_a?(NotModelledValue) && other.instance_variable_get(:@expression) == @expression
      end
      alias eql? ==

      def hash
        @expression.hash
      end

      def to_s
        receiver, call, arguments = @expression
        list = "(#{arguments.map(&:inspect).join(', ')})" unless arguments.empty? && call != :new
        "#{receiver}.#{call}#{list}"
      end
      alias inspect to_s

      private

      # The one place where any call on an instance is accepted: values of
      # classes this gem does not model. Ruby's implicit conversions are
      # not taken (see Ignored::CONVERSIONS).
      def method_missing(name, *arguments, **options, &)
        return super if Ignored::CONVERSIONS.include?(name)

        NotModelledValue.of(self, name, options.empty? ? arguments : [*arguments, options])
      end

      def respond_to_missing?(name, _include_private = false)
        !Ignored::CONVERSIONS.include?(name)
      end
    end
  end
end
