# frozen_string_literal: true

# Only what every command needs is loaded here: the command classes, their
# descriptions and options. What a command does (the model layer, the
# renderers, the generators...) is loaded when it runs (see Support and
# LIBRARIES): `syskit help` and `syskit --version` answer without it.
require 'thor'
require 'syskit/version'
require 'syskit/cli/support'
require 'syskit/cli/command_line'
require 'syskit/cli/style'
require 'syskit/cli/help'
require 'syskit/cli/terminal_width'

module Syskit
  # `syskit`: thin Thor commands that parse options, call one function of the
  # library and print its result.
  class CLI < Thor
    # What each command loads before it runs (see Help#libraries); the
    # others load the model layer, syskit, and the rest as they go. `gen`
    # and `bus` are groups: their commands say what they need.
    LIBRARIES = {
      'version' => [], 'gen' => [], 'bus' => [],
      'diff' => %w[syskit syskit/cli/plan_files], 'check' => %w[syskit syskit/check set],
      'doc' => %w[syskit syskit/doc], 'test' => %w[syskit syskit/test/runner],
      'lsp' => %w[syskit syskit/lsp set]
    }.freeze

    def self.libraries(command_name)
      LIBRARIES.fetch(command_name) { super }
    end

    def self.exit_on_failure?
      true
    end

    extend Help

    # Usage lines say syskit, however the command was started.
    def self.basename
      'syskit'
    end

    # The command line as users type it (see CommandLine), errors as
    # syskit prints them (see Shell).
    def self.start(given_args = ARGV, config = {})
      config[:shell] ||= Shell.new
      # Thor stops with a backtrace on an argument that is not UTF-8.
      bad = given_args.find { |arg| !Printable.utf8?(arg) }
      return CommandLine.not_text(bad) if bad

      super(CommandLine.normalize(given_args), config)
    end

    # Options every command takes, said once under the list of commands.
    COMMON_OPTIONS = <<~TEXT
      Every command takes --help (-h), and --trace: errors with Ruby's backtrace.
      syskit --version (-v) prints the version.
    TEXT

    # `syskit help`: the commands, then the options every command takes.
    def self.help(shell, subcommand = false) # rubocop:disable Style/OptionalBooleanParameter -- Thor's signature
      list = printable_commands(true, subcommand)
      Thor::Util.thor_classes_in(self).each { |klass| list += klass.printable_commands(false) }
      shell.say 'Commands:'
      shell.print_table(list.sort_by(&:first), indent: 2, truncate: true)
      shell.say
      shell.say COMMON_OPTIONS
    end

    include Support

    # Options are checked: a typo is an error, not a profile name. `syskit
    # test` hands the options it does not know to minitest.
    check_unknown_options!(except: %i[test])

    # --trace is accepted everywhere; the help says so once, in each
    # command's description, rather than as Thor's --[no-,skip-]trace.
    class_option :trace, type: :boolean, default: false, hide: true, desc: 'show the backtrace of errors'

    desc 'version', 'print the version (also: syskit --version, syskit -v)'
    def version
      $stdout.write(Syskit.version_text)
    end

    private

    # Warnings do not stop a plan (constructs of Rock files this gem does
    # not model, ...): one line on stderr says there are some.
    def note_warnings(app)
      count = app.problems.grep(Warning).size
      return unless count.positive?

      warn Style.for($stderr).warning("#{Naming.count(count, 'warning')} while loading (syskit check lists them)")
    end
  end
end

# The commands, a file each: their descriptions and options, not what they
# load when they run.
require 'syskit/cli/plan'
require 'syskit/cli/check'
require 'syskit/cli/doc'
require 'syskit/cli/test'
require 'syskit/cli/lsp'
require 'syskit/cli/bus'
require 'syskit/cli/gen'
