# frozen_string_literal: true

module Syskit
  # The checks DSL statements make of their arguments, so that a nil, a
  # missing block or a value of the wrong shape is reported at the user's
  # line with what to write, instead of the Ruby error it would cause
  # further on (+undefined method `to_sym' for nil+).
  #
  # Each check returns the value in the form the statement uses, or raises
  # +error_class+ (a Syskit::Error subclass: DeclarationError in model
  # files, SpecError in .orogen files, TypeError in typekits) located at
  # the first frame outside the gem: the statement's call.
  module Arguments
    # Names that become Ruby methods (attributes, properties, fields).
    METHOD_NAME = /\A[a-z_][A-Za-z0-9_]*\z/
    # Names of C++ identifiers (task contexts, enum values, struct names).
    IDENTIFIER = /\A[A-Za-z_][A-Za-z0-9_]*\z/
    # Names of ports: oroGen accepts any \w+ (+'3d_points'+).
    PORT_NAME = /\A[A-Za-z0-9_]+\z/
    # What the patterns above accept, said to users.
    RULES = {
      METHOD_NAME => 'a lower-case letter or _ first, then letters, digits and _',
      IDENTIFIER => 'a letter or _ first, then letters, digits and _',
      PORT_NAME => 'letters, digits and _'
    }.freeze
    # Values that never match a deployed task's name (deployment_hint?).
    NOT_DEPLOYMENT_HINTS = [NilClass, TrueClass, FalseClass, Numeric, Symbol].freeze

    module_function

    # +value+ (a String or Symbol matching +pattern+) as a String.
    # +statement+ names the call in messages ("dsl_attribute"), +what+ the
    # argument ("an attribute name"), +example+ a correct call.
    # +rule+ says what +pattern+ accepts (known for the patterns above).
    # Whether +hint+ may choose deployed tasks (+prefer_deployed_tasks+):
    # a name, a regexp, or any object matching names with === (a Proc...),
    # but not a value that never matches a name (a number, a symbol...).
    def deployment_hint?(hint)
      NOT_DEPLOYMENT_HINTS.none? { |klass| hint.is_a?(klass) }
    end

    def name(value, statement:, what:, example:, pattern: IDENTIFIER, rule: RULES[pattern],
             error_class: DeclarationError)
      given(value, statement: statement, what: what, example: example, error_class: error_class)
      text = value.to_s if value.is_a?(String) || value.is_a?(Symbol)
      return text if text&.valid_encoding? && text.match?(pattern)

      raise error_class.new("#{statement} expects #{what}, got #{shown(value)}",
                            location: Location.of_caller,
                            hint: "write #{example}#{" (names have #{rule})" if rule}")
    end

    # +value+, which must not be nil.
    def given(value, statement:, what:, example:, error_class: DeclarationError)
      return value unless value.nil?

      raise error_class.new("#{statement} needs #{what}", location: Location.of_caller, hint: "write #{example}")
    end

    # The block a statement evaluates, which must be given.
    def block(block, statement:, example:, error_class: DeclarationError)
      return block if block

      raise error_class.new("#{statement} needs a block", location: Location.of_caller, hint: "write #{example}")
    end

    # A non-empty list of distinct names, as Strings.
    def names(value, statement:, what:, example:, pattern: IDENTIFIER, error_class: DeclarationError)
      list = value.is_a?(Array) ? value : nil
      if list.nil? || list.empty?
        raise error_class.new("#{statement} expects a non-empty list of #{what}, got #{shown(value)}",
                              location: Location.of_caller, hint: "write #{example}")
      end

      list = list.map do |v|
        name(v, statement: statement, what: what, example: example, pattern: pattern, error_class: error_class)
      end
      duplicate, = list.tally.find { |_, count| count > 1 }
      return list unless duplicate

      raise error_class.new("#{statement} lists '#{duplicate}' twice", location: Location.of_caller,
                                                                       hint: 'give each value once')
    end

    # How each kind of parameter (Method#parameters) is written in a call.
    AS_WRITTEN = { req: '%s', opt: '%s = ...', rest: '*%s', keyreq: '%s:', key: '%s: ...', keyrest: '**%s',
                   block: '&%s' }.freeze

    # The parameters +parameters+ (as Method#parameters gives them) as they
    # are written in a call, for hints: ['id', 'mask = ...'].
    def as_written(parameters)
      parameters.map { |kind, name| format(AS_WRITTEN.fetch(kind), name) }
    end

    # A value as the user wrote it, cut short when long.
    def shown(value)
      text = value.inspect
      text.size > 60 ? "#{text[0, 57]}..." : text
    end
  end
end
