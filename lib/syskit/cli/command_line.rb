# frozen_string_literal: true

require 'thor'
require 'syskit/printable'
require 'syskit/cli/command_table'

module Syskit
  class CLI < Thor
    # What `syskit` users type that Thor reads otherwise: `--version`/`-v`
    # alone is the version command, and `--help`/`-h` after a command is
    # that command's help (`syskit plan --help` is `syskit help plan`,
    # `syskit gen dev -h` is `syskit gen help dev`). Everything else goes to
    # Thor as given.
    module CommandLine
      HELP = %w[-h --help].freeze
      VERSION = %w[-v --version].freeze
      # Commands that have commands of their own.
      GROUPS = %w[gen bus].freeze

      # Commands of Rock's Syskit that users of it type, with what this gem
      # offers instead: `syskit instanciate` and `syskit ide` need Roby (and
      # Qt), which this gem does without.
      ROCK_COMMANDS = {
        'instanciate' => ['builds the network of actions in Roby',
                          'syskit plan [PROFILE] [ACTION...] prints the network of a profile or of some of its ' \
                          'actions (e.g. syskit plan Live::Base gps_dev)'],
        'ide' => ['browses models and networks in a Qt window',
                  "syskit doc writes the app's models and plans as pages to browse, and syskit plan --format svg " \
                  'draws a plan'],
        'run' => ['runs the robot under Roby and Orocos',
                  'syskit plan and syskit check show, before the robot runs, what Syskit would deploy']
      }.freeze

      module_function

      def normalize(args)
        return ['version'] if args.size == 1 && VERSION.include?(args.first)

        options = args.take_while { |a| a != '--' }
        return args unless options.size > 1 && options.drop(1).intersect?(HELP)

        command, sub = options.reject { |a| HELP.include?(a) }
        return [command, 'help', *(sub unless sub&.start_with?('-'))] if GROUPS.include?(command)

        ['help', command]
      end

      # An argument that is not UTF-8 text: refused before Thor reads it.
      def not_text(arg)
        warn Error.new("the argument '#{Printable.text(arg)}' is not UTF-8 text",
                       hint: 'arguments are names and paths written in UTF-8; rename a file whose name is not')
                  .report
        exit 1
      end
    end

    # Thor's own errors (an unknown option, a missing argument) as syskit
    # prints errors: a message then a hint.
    class Shell < Thor::Shell::Basic
      # Lists of commands, which Thor cuts at the terminal's width: see
      # CommandTable.
      def print_table(array, options = {})
        return super unless options[:truncate] && array.all? { |row| row.size == 2 }

        stdout.puts CommandTable.lines(array, indent: options[:indent].to_i,
                                              width: Thor::Shell::Terminal.terminal_width)
      end

      def error(message)
        if (option = message[/\AUnknown switches ["'](.*?)["']/, 1])
          message = "unknown option '#{option}'\n  hint: `syskit help COMMAND` lists the options of a command"
        end
        super
      end
    end
  end
end
