# frozen_string_literal: true

module Syskit
  module Compat
    # +Orocos+, Rock's component runtime, as model and test files name it:
    # its exception classes (+assert_raises(Orocos::StateTransitionFailed)+
    # in a test that needs the runtime, and is skipped before it gets
    # there), +Orocos.allow_blocking_calls { ... }+, which runs its block;
    # any other call or constant is accepted with a "not modelled" warning.
    module Orocos
      # The base of Orocos' errors.
      class Error < RuntimeError; end

      ERRORS = %i[NotFound NotOrogenComponent NoModel ComError CORBAError StateTransitionFailed
                  ConnectionFailed InterfaceObjectNotFound TypekitTypeNotFound TypekitTypeNotExported
                  BlockingCallInForbiddenThread ConfigurationError PropertyChangeRejected].freeze
      ERRORS.each { |name| const_set(name, Class.new(Error)) }

      extend NotModelledCalls

      class << self
        # Calls that would block on a component are allowed in the block:
        # it runs (there is no component to block on).
        def allow_blocking_calls
          yield if block_given?
        end

        def to_s
          'Orocos'
        end
        alias inspect to_s

        # +Orocos::Async+, +Orocos::RubyTasks+...: the runtime's classes.
        def const_missing(name)
          Syskit.app&.not_modelled("Orocos::#{name}", Location.of_caller)
          IgnoredNamespace
        end
      end
    end
  end
end
