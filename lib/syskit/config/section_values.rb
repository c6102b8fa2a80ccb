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
        properties[key].write(numbers(file, names, key).convert(properties.declarations.fetch(key).type, value))
      rescue Types::ValueError => e
        raise ConfigurationError.new("property '#{key}' of #{properties.class.task_model.name}: #{e.message}",
                                     location: file.location_of(key, names),
                                     hint: 'write a number, optionally followed by units: 0.5, 2.deg, 150.ms')
      rescue ConfigurationError => e
        raise e.at(file.location_of(key, names))
      end

      # Numbers written with units or a rounding (2.deg, 2.5.round), read
      # as Rock's loader reads them; its warnings are the app's, at the
      # line of +key+.
      def numbers(file, names, key)
        NumbersWithUnits.new do |message, hint|
          Syskit.app&.warning("#{key}: #{message}", location: file.location_of(key, names), hint: hint)
        end
      end

      # The problems of each section of +file+ set alone on a fresh
      # +properties+ of +task_model+, in the order of the file.
      def problems(file, task_model)
        file.sections.each_value.flat_map do |section|
          properties = task_model.properties_class.initial
          section.settings.filter_map do |key, value|
            apply(properties, file, [section.name], key, value)
            nil
          rescue ConfigurationError => e
            e
          end
        end
      end

      def unknown_property(properties, file, names, key)
        known = properties.names
        section = file.section_of(key, names).name
        ConfigurationError.new(
          "#{properties.class.task_model.name} has no property '#{key}'#{Naming.did_you_mean(key, known)} " \
          "(section '#{section}' of #{File.basename(file.path)})",
          location: nil, hint: "its properties are #{known.sort.join(', ').then { |s| s.empty? ? '(none)' : s }}"
        )
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
