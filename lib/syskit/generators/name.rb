# frozen_string_literal: true

require 'syskit/naming'
require 'syskit/errors'

module Syskit
  module Generators
    # A name given to a generator, in path form (gps/ublox/f9) or constant
    # form (GPS::Ublox::F9), as the constants it defines and the path of its
    # files. The path is always derived from the constants, so that both
    # forms of one name land in the same file.
    class Name
      EXAMPLES = 'e.g. gps/ublox/f9 or GPS::Ublox::F9'

      # Words separated by single underscores; camelize needs no more.
      SEGMENT = /\A[A-Za-z0-9]+(_[A-Za-z0-9]+)*\z/

      attr_reader :constants

      # Parses +text+ for a generator of +what+ ('device', 'profile'...);
      # raises GeneratorError when it cannot name Ruby constants in the app.
      # +examples+ are shown in the hints of errors.
      def self.parse(text, what:, acronyms: [], examples: EXAMPLES)
        text = text.to_s.strip
        refuse_path(text, what, examples)
        segments = text.include?('::') ? text.split('::', -1) : text.split('/', -1)
        constants = segments.map { |segment| constant_for(segment, text, what, acronyms, examples) }
        new(constants)
      end

      # Checks that a file name given by the user stays where it is meant to.
      def self.refuse_path(text, what, examples = EXAMPLES)
        if text.empty?
          raise GeneratorError.new("a #{what} needs a name", hint: "give one, #{examples}")
        elsif text.start_with?('/', '~')
          raise GeneratorError.new("'#{text}' is an absolute path, a #{what} name is not",
                                   hint: "give the name relative to the app's models, #{examples}")
        elsif text.split(%r{/|::}).include?('..')
          raise GeneratorError.new("'#{text}' contains '..': a #{what} cannot leave the app's models/ and test/",
                                   hint: "give the name relative to the app's models, #{examples}")
        end
      end

      def self.constant_for(segment, text, what, acronyms, examples)
        constant = Naming.camelize(segment, acronyms) if SEGMENT.match?(segment)
        return constant if constant && Naming.constant_name?(constant)

        shown = segment.empty? ? "an empty part (a doubled or trailing '/' or '::')" : "'#{segment}'"
        raise GeneratorError.new(
          "'#{text}' is not a valid #{what} name: #{shown} does not make a Ruby constant name",
          hint: 'each part must start with a letter and contain only letters, digits and single ' \
                "underscores, #{examples}"
        )
      end
      private_class_method :constant_for

      def initialize(constants)
        @constants = constants.freeze
        freeze
      end

      # The last constant: 'F9' of GPS::Ublox::F9.
      def basename
        constants.last
      end

      # The enclosing constants: %w[GPS Ublox] of GPS::Ublox::F9.
      def namespace
        constants[0..-2]
      end

      # The snake_case path segments: %w[gps ublox f9].
      def path_segments
        constants.map { |c| Naming.underscore(c) }
      end

      # The relative path without extension: 'gps/ublox/f9'.
      def path
        path_segments.join('/')
      end

      # The model file: models/KIND/gps/ublox/f9.rb.
      def model_path(kind)
        File.join('models', kind, "#{path}.rb")
      end

      # test/KIND/gps/ublox/test_f9.rb, the test of the model at #model_path.
      def test_path(kind)
        File.join('test', kind, *path_segments[0..-2], "test_#{path_segments.last}.rb")
      end

      # The constant form: 'GPS::Ublox::F9'.
      def to_s
        constants.join('::')
      end

      # This name with +prefix+ constants in front unless it starts with them
      # (bus/can and can are both Bus::CAN).
      def under(*prefix)
        return self if constants.first(prefix.size) == prefix && constants.size > prefix.size

        Name.new(prefix + constants)
      end
    end
  end
end
