# frozen_string_literal: true

require 'syskit/config/numbers_with_units'

module Syskit
  module Config
    # A configuration file's values checked against a task model as they
    # are set on its properties: by the generator, for the sections a
    # device asks for (merged), and by `syskit check`, for every section of
    # every file on its own, as Rock checks a file when it loads it, so
    # that a typo in a section no profile uses is found too.
    module SectionValues
      module_function

      # properties[key] = value, the value coming from the sections +names+
      # of +file+; raises a ConfigurationError at the line of +key+.
      def apply(properties, file, names, key, value)
        raise unknown_property(properties, file, names, key) unless properties.include?(key)

        check_symbol(properties, key, value)
        properties[key].write(with_units(properties, file, names, key, value))
      rescue Types::ValueError => e
        raise ConfigurationError.new("property '#{key}' of #{properties.class.task_model.name}: #{e.message}",
                                     location: file.location_of(key, names),
                                     hint: 'write a number, optionally followed by units: 0.5, 2.deg, 150.ms')
      rescue ConfigurationError => e
        raise e.at(file.location_of(key, names))
      end

      # +value+ with its numbers written with units read (see #numbers).
      # Only text and containers can hold any, and a float given to an
      # integer field is rounded: other values (most are plain numbers) are
      # taken as they are, without a converter made for each.
      def with_units(properties, file, names, key, value)
        type = properties.declarations.fetch(key).type
        case value
        when String, Array, Hash then numbers(file, names, key).convert(type, value)
        when Float then type.is_a?(Types::IntegerType) ? numbers(file, names, key).convert(type, value) : value
        else value
        end
      end

      # Numbers written with units or a rounding (2.deg, 2.5.round), read
      # as Rock's loader reads them; its warnings are the app's, at the
      # line of +key+.
      def numbers(file, names, key)
        NumbersWithUnits.new do |message, hint|
          Syskit.app&.warning("#{key}: #{message}", location: file.location_of(key, names), hint: hint)
        end
      end

      # Unknown properties of one file reported in full; the others are
      # counted in one more error (see #more_unknown).
      SHOWN = 10

      # The problems of each section of +file+ set alone on a fresh
      # +properties+ of +task_model+: the values of known properties in the
      # order of the file, then its unknown properties, the first SHOWN of
      # them each in full. Unknown keys are found by a lookup, not by
      # raising: a file with 200,000 of them is checked in linear time.
      def problems(file, task_model)
        unknown = []
        found = file.sections.each_value.flat_map do |section|
          properties = task_model.properties_class.initial
          section.settings.filter_map do |key, value|
            if properties.include?(key)
              apply(properties, file, [section.name], key, value)
            else
              unknown << [section.name, key]
            end
            nil
          rescue ConfigurationError => e
            e
          end
        end
        found + unknown_properties(file, task_model, unknown)
      end

      # The errors of +unknown+ ([section name, key] pairs, in the order of
      # the file).
      def unknown_properties(file, task_model, unknown)
        properties = task_model.properties_class.initial
        shown = unknown.first(SHOWN).map do |name, key|
          unknown_property(properties, file, [name], key).at(file.location_of(key, [name]))
        end
        rest = unknown.drop(SHOWN)
        rest.empty? ? shown : shown << more_unknown(properties, file, rest)
      end

      # One error for the unknown properties of a file past the first
      # SHOWN, at the line of the first of them, saying how many there are.
      def more_unknown(properties, file, rest)
        name, key = rest.first
        keys = rest.first(3).map { |_, k| "'#{k}'" }.join(', ')
        ConfigurationError.new(
          "#{rest.size} more #{rest.size == 1 ? 'property' : 'properties'} that " \
          "#{properties.class.task_model.name} does not have in #{File.basename(file.path)} " \
          "(#{keys}#{', ...' if rest.size > 3}; the first #{SHOWN} are listed one by one)",
          location: file.location_of(key, [name]), hint: unknown_hint(properties.names)
        )
      end

      def unknown_property(properties, file, names, key)
        known = properties.names
        section = file.section_of(key, names).name
        ConfigurationError.new(
          "#{properties.class.task_model.name} has no property '#{key}'#{Naming.did_you_mean(key, known)} " \
          "(section '#{section}' of #{File.basename(file.path)})",
          location: nil, hint: unknown_hint(known)
        )
      end

      def unknown_hint(known)
        "its properties are #{known.sort.join(', ').then { |s| s.empty? ? '(none)' : s }}"
      end

      # A symbol in a configuration file (deviceType: :SOCKET) is an enum
      # value: refused for a property that is not an enum.
      def check_symbol(properties, key, value)
        type = properties.declarations.fetch(key).type
        return unless value.is_a?(Symbol) && !type.is_a?(Types::EnumType) && !type.opaque?

        raise ConfigurationError.new(
          "#{key}: #{value.inspect} is a symbol, which only enum properties take (#{key} is a #{type})",
          location: nil, hint: "write the value without its leading colon: #{key}: #{value}"
        )
      end
    end
  end
end
