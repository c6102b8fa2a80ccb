# frozen_string_literal: true

module Syskit
  module Models
    # Task arguments of task models (+argument :port, default: '/dev/ttyS0'+),
    # as Rock's extension files declare them.
    module TaskArguments
      # Declares a task argument, readable in configure as a method of the
      # task: +argument :port, default: '/dev/ttyS0'+. Profiles set
      # arguments through compositions, which are not modelled: every
      # task has its arguments' defaults. An argument declared without a
      # default is required, as in Syskit: reading it unset is an error
      # that says how to set it.
      def argument(name, default: NO_DEFAULT, doc: nil)
        location = Location.of_caller
        name = name.to_sym
        if name.end_with?('_dev') || !name.match?(/\A[a-z_]\w*\z/)
          raise DeclarationError.new("'#{name}' is not a valid argument name",
                                     location: location, hint: 'arguments are lower-case names not ending in _dev')
        end

        (@argument_declarations ||= {})[name] = [default, location, doc]
        Component.declarations_changed
        define_method(name) do
          value = arguments.fetch(name) { self.class.argument_default(name, Location.of_caller) }
          value.is_a?(Compat::Roby::DefaultArgument) ? value.value : value
        end
        # As on a Roby task, tests set arguments on an instance (+task.x = 1+):
        # in place, as merging tasks does; frozen ones are replaced.
        define_method("#{name}=") do |value|
          if arguments.frozen?
            @arguments = arguments.merge(name => value)
          else
            arguments[name] = value
          end
        end
        name
      end

      # What +argument+ is when it is not set: its default, or an error
      # at +location+ (where configure reads it) when it has none.
      def argument_default(name, location)
        default, declared_at = argument_declarations.fetch(name)
        return default unless default.equal?(NO_DEFAULT)

        raise ConfigureMethodError.new(
          "argument '#{name}' of #{self.name} is not set (declared at #{declared_at})",
          location: location, hint: "pass it with with_arguments(#{name}: ...), or give it a default"
        )
      end

      # The documentation given to the argument +name+ (doc:), or nil.
      def argument_doc(name)
        argument_declarations.fetch(name.to_sym, [])[2]
      end

      # Default values of the arguments declared with {#argument}, inherited
      # ones included (nil for a required argument).
      def argument_defaults
        model_argument_declarations.transform_values { |default, _| default.equal?(NO_DEFAULT) ? nil : default }
      end

      # The arguments the model declares beyond those every task of its
      # kind has (+conf+, +read_only+, declared by TaskContext, Composition
      # and Component): what Syskit lists as a definition's arguments.
      def model_argument_declarations
        root = [Syskit::TaskContext, Syskit::Composition, Syskit::Component].find { |m| self <= m }
        return argument_declarations if root.nil? || equal?(root)

        argument_declarations.except(*root.argument_declarations.keys)
      end

      # The arguments a new task starts with, as Roby's: each declared
      # argument that has a default, as a Roby::DefaultArgument (not set,
      # see Compat::Roby::TaskArguments#set?).
      #
      # Every task of the model starts with them: they are made once per
      # model (frozen, DefaultArgument being a frozen value), and made again
      # after declarations changed on any model (see Component#cached), this
      # one's parents included.
      def default_arguments
        cached(:default_arguments) do
          argument_declarations.each_with_object({}) do |(name, (default, _)), defaults|
            defaults[name] = Compat::Roby::DefaultArgument.new(default) unless default.equal?(NO_DEFAULT)
          end.freeze
        end
      end

      # Whether +name+ (a symbol) is an argument declared with +argument+,
      # here or in a parent model.
      def argument_declared?(name)
        @argument_declarations&.key?(name) ||
          (superclass.respond_to?(:argument_declared?) && superclass.argument_declared?(name))
      end

      # Whether the model has the argument +name+: declared with
      # #argument, or holding the device of a driver service (Syskit
      # declares +<as>_dev+ for each +driver_for+).
      def has_argument?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        name = name.to_sym
        argument_declared?(name) || (respond_to?(:device_argument?) && device_argument?(name))
      end

      def argument_declarations
        inherited = superclass.respond_to?(:argument_declarations) ? superclass.argument_declarations : {}
        inherited.merge(@argument_declarations || {})
      end

      # The default of an argument declared without one.
      NO_DEFAULT = Object.new.freeze
    end
  end
end
