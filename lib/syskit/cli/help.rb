# frozen_string_literal: true

module Syskit
  class CLI < Thor
    # How syskit's commands describe themselves (extended by `syskit`,
    # `syskit gen` and `syskit bus`): without Thor's own `tree` command,
    # and flags without the --no-/--skip- forms Thor adds to them.
    module Help
      # What the command +command_name+ loads before it runs: the model
      # layer, unless a command class says otherwise. Help loads nothing.
      def libraries(_command_name)
        %w[syskit]
      end

      def printable_commands(all = true, subcommand = false) # rubocop:disable Style/OptionalBooleanParameter -- Thor's signature
        super.reject { |usage, _| usage.match?(/\A\S+(?: \S+)? tree\z/) }
      end

      # A command Thor does not know: Rock's Syskit commands say what to
      # use instead, others what was meant.
      def handle_no_command_error(command, _has_namespace = nil)
        full = "#{command_prefix}#{command}"
        if (what, hint = CommandLine::ROCK_COMMANDS[full])
          raise Thor::Error, "syskit #{full} is a command of Rock's Syskit, which #{what}: this gem has no " \
                             "runtime\n  hint: #{hint}"
        end

        require 'syskit/naming'
        guess = Naming.suggest(command, all_commands.keys - ['tree']).first
        meant = guess ? " (did you mean 'syskit #{command_prefix}#{guess}'?)" : ''
        raise Thor::Error, "unknown command 'syskit #{full}'#{meant}\n  " \
                           "hint: syskit #{command_prefix}help lists the commands"
      end

      # Arguments missing or too many: what the command takes.
      def handle_argument_error(command, _error, args, _arity)
        what = args.empty? ? 'needs arguments' : "does not take the arguments #{args.join(' ')}"
        name = "syskit #{command_prefix}#{command.name}"
        raise Thor::InvocationError, "#{name} #{what}\n  hint: usage: syskit #{command_prefix}#{command.usage} " \
                                     "(#{name} --help tells more)"
      end

      # 'gen ' for `syskit gen`'s commands, '' for syskit's own.
      def command_prefix
        self == CLI ? '' : "#{name.split('::').last.downcase} "
      end

      def print_options(shell, options, group_name = nil)
        # Loaded by the help of a command, which alone shows options.
        require 'syskit/cli/help_flag'
        super(shell, options.map { |option| option.boolean? ? Flag.new(option) : option }, group_name)
      end
    end
  end
end
