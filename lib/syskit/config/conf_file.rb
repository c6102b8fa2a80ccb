# frozen_string_literal: true

require 'psych'

module Syskit
  module Config
    # A task model's configuration file, config/orogen/<lib>::<Task>.yml:
    #
    #   --- name:default
    #   device: can0
    #   --- name:forward
    #   ip: 10.40.50.50
    #
    # A file without a header starts with the 'default' section. Sections are
    # read with safe YAML only (no Ruby objects, no aliases).
    class ConfFile
      HEADER = /^---\s*name:\s*(\S+)\s*$/.freeze

      # One section: its values and the line of its header.
      Section = Struct.new(:name, :values, :line, :text)

      attr_reader :path, :sections

      def initialize(path)
        @path = path
        @sections = {}
        parse(File.read(path))
      end

      def section_names
        sections.keys
      end

      # The values of +names+ merged left to right: later sections override
      # earlier ones, hashes are merged key by key. 'default' may be missing.
      def merged(names, location:)
        (@merged ||= {})[names] ||= merge_sections(names, location).freeze
      end

      def merge_sections(names, location)
        names.reduce({}) do |values, name|
          section = sections[name]
          next values if section.nil? && name == 'default'

          raise unknown_section(name, location) unless section

          ConfFile.deep_merge(values, section.values)
        end
      end

      # The location of +key+ in the section that set it last among +names+.
      def location_of(key, names)
        names.reverse_each do |name|
          section = sections[name]
          next unless section&.values&.key?(key)

          offset = section.text.lines.index { |l| l.match?(/^#{Regexp.escape(key)}\s*:/) }
          return Location.new(path, section.line + 1 + offset.to_i)
        end
        Location.new(path, 1)
      end

      def self.deep_merge(base, override)
        base.merge(override) do |_key, old, new|
          old.is_a?(Hash) && new.is_a?(Hash) ? deep_merge(old, new) : new
        end
      end

      private

      def parse(text)
        current = ['default', 1, []]
        chunks = []
        text.each_line.with_index(1) do |line, lineno|
          if (m = line.match(HEADER))
            chunks << current
            current = [m[1], lineno, []]
          else
            current[2] << line
          end
        end
        chunks << current
        chunks.shift if chunks.first[2].all? { |l| l.strip.empty? || l.strip.start_with?('#') } && chunks.size > 1
        chunks.each { |name, line, lines| add_section(name, line, lines.join) }
      end

      def add_section(name, line, text)
        if (other = sections[name])
          raise ConfigurationError.new("section '#{name}' is declared twice (first at line #{other.line})",
                                       location: Location.new(path, line), hint: 'merge the two sections')
        end

        sections[name] = Section.new(name, load_yaml(text, line), line, text)
      end

      def load_yaml(text, header_line)
        # Blank lines keep Psych's line numbers those of the file.
        values = Psych.safe_load("\n" * header_line + text, filename: path, aliases: false) || {}
        return values if values.is_a?(Hash)

        raise ConfigurationError.new('a configuration section must map property names to values',
                                     location: Location.new(path, header_line + 1), hint: 'write property: value lines')
      rescue Psych::DisallowedClass, Psych::BadAlias => e
        marker = e.is_a?(Psych::BadAlias) ? /[&*]\w/ : /!/
        raise ConfigurationError.new("refused: #{e.message}", location: line_of(marker, text, header_line),
                                                               hint: 'configuration files hold plain data: no tags, no aliases')
      rescue Psych::SyntaxError => e
        raise ConfigurationError.new("invalid YAML: #{e.problem}", location: Location.new(path, e.line),
                                                                    hint: 'fix the YAML syntax at this line')
      end

      # The first line of a section's +text+ matching +marker+.
      def line_of(marker, text, header_line)
        offset = text.lines.index { |l| l.match?(marker) }
        Location.new(path, offset ? header_line + 1 + offset : header_line)
      end

      def unknown_section(name, location)
        known = section_names
        ConfigurationError.new(
          "no section '#{name}' in #{File.basename(path)}#{Naming.did_you_mean(name, known)} " \
          "(sections: #{known.join(', ')})",
          location: location,
          hint: "add '--- name:#{name}' to #{File.basename(path)}; with_conf replaces ['default'], " \
                "so write with_conf('default', '#{name}') to apply both"
        )
      end
    end
  end
end
