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

      # orocos.rb's test helpers.
      module Test
        # oroGen packages' own component tests (+include
        # Orocos::Test::Component+, then +start 'task', 'lib::Task' =>
        # 'task'+, +reader+, +writer+ in the test class): they start the
        # component, so each of their tests skips, saying so.
        module Component
          REASON = "Orocos::Test::Component starts components: needs Orocos' runtime"

          def self.included(base)
            super
            base.extend(ClassMethods)
          end

          # The class statements that declare what the tests start and
          # read: accepted, nothing is started.
          module ClassMethods
            %i[start reader writer logger_task].each do |name|
              define_method(name) { |*_args, **_options, &_block| nil }
            end
          end

          def before_setup
            super
            skip(REASON)
          end
        end
      end

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
