# frozen_string_literal: true

module Syskit
  module Models
    # Task arguments of task models (+argument :port, default: '/dev/ttyS0'+),
    # as Rock's extension files declare them.
    module TaskArguments
      # Declares a task argument, readable in configure as a method of the
      # task: +argument :port, default: '/dev/ttyS0'+. Profiles set
      # arguments through compositions, which are not modelled: every
      # task has its arguments' defaults.
      def argument(name, default: nil, doc: nil) # rubocop:disable Lint/UnusedMethodArgument -- Syskit's signature
        name = name.to_sym
        if name.end_with?('_dev') || !name.match?(/\A[a-z_]\w*\z/)
          raise DeclarationError.new("'#{name}' is not a valid argument name",
                                     location: Location.of_caller,
                                     hint: 'arguments are lower-case names not ending in _dev')
        end

        (@argument_defaults ||= {})[name] = default
        define_method(name) { arguments.fetch(name) { self.class.argument_defaults[name] } }
        name
      end

      # Default values of the arguments declared with {#argument}, inherited ones included.
      def argument_defaults
        inherited = superclass.respond_to?(:argument_defaults) ? superclass.argument_defaults : {}
        inherited.merge(@argument_defaults || {})
      end
    end
  end
end
