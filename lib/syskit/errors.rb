# frozen_string_literal: true

require 'syskit/location'

module Syskit
  # What every error a user can meet says: what is wrong, where (the
  # user's file and line) and how to fix it.
  module Reported
    attr_reader :location, :hint

    # The error for a terminal: "file:line: message" then an indented hint.
    def report(root = nil)
      first = location ? "#{location.to_s(root)}: #{one_line(message)}" : one_line(message)
      hint ? "#{first}\n  hint: #{one_line(hint)}" : first
    end

    # The error as plain data, for `--format json`.
    def to_h(root = nil)
      {
        'file' => location&.relative_path(root), 'line' => location&.lineno,
        'severity' => 'error', 'message' => message, 'hint' => hint
      }
    end

    # What makes two reports of a problem the same one (check and load
    # keep it once).
    def identity
      [self.class, message, location.to_a]
    end

    # Copy of this error whose message says first where it happened
    # ("in gps::Task's configure: ...").
    def in_context(context)
      copy = self.class.new("#{context}: #{message}", location: location, hint: hint)
      copy.set_backtrace(backtrace) if backtrace
      copy
    end

    # Copy of this error pointing at another location, when the first
    # location found is not the user's (e.g. inside a bundled model).
    def at(location)
      copy = dup
      copy.instance_variable_set(:@location, location)
      copy
    end

    # Copy of this error without its hint, for a report that gave the same
    # hint above.
    def without_hint
      copy = dup
      copy.instance_variable_set(:@hint, nil)
      copy
    end

    private

    def locate(location, hint)
      @location = location
      @hint = hint
    end

    # Names from user files may hold newlines; a report keeps one line each.
    def one_line(text)
      text.to_s.gsub("\n", '\n')
    end
  end

  # Base of every error a user can meet.
  class Error < StandardError
    include Reported

    # Without a message (+raise Syskit::Ambiguous+), the class name is the
    # message, as for Ruby's own exceptions.
    def initialize(message = self.class.name, location: nil, hint: nil)
      super(message)
      locate(location, hint)
    end

    # `rescue Syskit::Error` also catches DeclarationError, which must be a
    # Ruby ArgumentError as well.
    def self.===(other)
      super || (equal?(Error) && other.is_a?(Reported))
    end
  end

  # Misuse of the modelling DSL: a declaration that cannot mean anything.
  # It is a Ruby ArgumentError too, as Syskit raises ArgumentError for the
  # same misuses (+assert_raises(ArgumentError) { cmp.add(srv) }+).
  class DeclarationError < ArgumentError
    include Reported

    def initialize(message, location: nil, hint: nil)
      super(message)
      locate(location, hint)
    end
  end

  # An invalid value given to a device attribute (a CAN id beyond 29
  # bits), as Rock's tests expect it (+assert_raises(ArgumentError) {
  # dev.can_id(...) }+).
  class InvalidArgument < DeclarationError; end

  # A name (device, bus, property...) that is not known.
  class UnknownName < DeclarationError; end

  # A service asked for by its model when a component has several of it.
  class AmbiguousServiceSelection < DeclarationError; end

  # A file of the app that cannot be loaded: syntax errors, exceptions raised
  # while it is evaluated, unknown task libraries or typekits.
  class FileLoadError < Error; end

  # An error that follows from another one already reported (a task
  # library missing because the file that loads it failed): the app keeps
  # the cause only, one error per cause.
  class FollowOnError < FileLoadError; end

  # A type that does not exist or a value that does not fit its type.
  class TypeError < Error; end

  # An .orogen task library specification that cannot be read.
  class SpecError < Error; end

  # A device without a usable driver, or with too many.
  class DriverError < Error; end

  # A network that cannot be generated from a profile.
  class NetworkError < Error; end

  # No, or too many, deployed tasks for a task of the network.
  class DeploymentError < NetworkError
    # The task that has no deployed task, when the error is about one (see
    # Network::Deploy): profile assertions list them.
    attr_accessor :task
  end

  # A configuration file or section that cannot be applied.
  class ConfigurationError < Error; end

  # An exception raised by a user's configure method or stub block.
  class ConfigureMethodError < ConfigurationError; end

  # A CAN bus that cannot carry its declared frames in time.
  class TimingError < Error; end

  # A generator that refuses to run.
  class GeneratorError < Error; end

  # Syskit's "cannot find a concrete implementation": a network needs a
  # component that is abstract, and nothing selects one for it. +abstract+
  # is what stands for it: the requirements (a tag's), or the abstract
  # model.
  class TaskAllocationFailed < NetworkError
    attr_reader :abstract

    def initialize(message, abstract: nil, **options)
      super(message, **options)
      @abstract = abstract
    end
  end

  # A tag of +profile+ that nothing selects: an error where the tag is
  # used, but not for the profile declaring it, which leaves it to the
  # profiles using it (Syskit's generic profiles).
  class UnselectedTag < TaskAllocationFailed
    attr_reader :profile

    def initialize(message, profile:, **options)
      super(message, **options)
      @profile = profile
    end

    # Whether +error+ (one error or several) is only tags of +profile+
    # nothing selects.
    def self.only_tags_of?(error, profile)
      errors = error.respond_to?(:errors) ? error.errors : [error]
      errors.all? { |e| e.is_a?(UnselectedTag) && e.profile.equal?(profile) }
    end
  end

  # Several errors found in one pass (loading an app, one generation step).
  class ErrorList < Error
    attr_reader :errors

    def initialize(errors)
      @errors = errors.flat_map { |e| e.respond_to?(:errors) ? e.errors : [e] }
      super(@errors.map(&:message).join("\n"), location: @errors.first&.location,
                                               hint: @errors.first&.hint)
    end

    def report(root = nil)
      @errors.map { |e| e.report(root) }.join("\n")
    end

    # Raises the errors as one exception, the single error itself when alone.
    def self.raise_if_any(errors)
      return if errors.empty?
      raise errors.first if errors.size == 1

      raise new(errors)
    end
  end

  # A problem that does not stop the plan but that the user should know of
  # (e.g. overlapping CAN filters). `syskit check --strict` makes them errors.
  class Warning < Error
    def to_h(root = nil)
      super.merge('severity' => 'warning')
    end

    def report(root = nil)
      text = super
      location ? text.sub(': ', ': warning: ') : "warning: #{text}"
    end
  end

  # A construct of real Rock files that this gem does not model
  # (Roby tasks and actions, runtime-only blocks): accepted,
  # with no effect on plans. `syskit check` lists them.
  class NotModelled < Warning
    def initialize(what, location: nil)
      super("#{what}: not modelled by this gem, ignored in the plan",
            location: location,
            hint: 'syskit plans devices, buses, their drivers and compositions; this has no effect on the plan')
    end
  end
end
