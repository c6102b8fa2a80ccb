# frozen_string_literal: true

require 'psych'
require 'syskit/config/embedded_ruby'

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
    # read with safe YAML only (no Ruby objects, no aliases), once the Ruby
    # expressions they embed (<%= ... %>, as in Rock) are replaced by their
    # values (see EmbeddedRuby).
    #
    # A header holds option:value words, as Rock's loader reads them:
    # +name:x+, +merge:true+ (the section is merged into the one of the same
    # name that a bundle's file declares, instead of replacing it) and
    # +chain:a,b+ (the sections a and b, declared before, merged into this
    # one, their values winning, as in Rock). Anything else on a header
    # line, a comment included, is refused as Rock's loader refuses it.
    class ConfFile
      # A section header: any line that starts with ---.
      HEADER = /\A---/
      HEADER_OPTIONS = %w[name merge chain].freeze
      # What YAML reads as a date or a time (a value, a list item).
      DATE = /(?:\A\s*|:\s*|-\s+|[\[,]\s*)(\d{4}-\d\d?-\d\d?(?:[Tt ]\S+)?)/

      # One section: its values, the file and line of its header (0 for a
      # 'default' section without one: its text starts at line 1), its text.
      Section = Struct.new(:name, :settings, :line, :text, :path) do
        # The offset in the text of the line setting +key+, when it is
        # found by ConfFile.key_lines (made once, when first asked).
        def key_line(key)
          (@key_lines ||= ConfFile.key_lines(text))[key]
        end
      end

      attr_reader :path, :sections

      # +base+: the file of the same task in a bundle this app uses, whose
      # sections this file's replace (or merge into, with merge:true).
      def initialize(path, base: nil)
        @path = path
        @sections = base ? base.sections.dup : {}
        parse(UserFile.read(path))
      end

      # A file without sections, for a task model that has none (+path+ is
      # only its name in messages).
      def self.empty(path)
        file = allocate
        file.instance_variable_set(:@path, path)
        file.instance_variable_set(:@sections, {})
        file
      end

      # A copy whose sections +names+ have +data+ merged into them (made
      # when missing), declared at +location+: what a test stubs.
      def with_sections(names, data, location)
        copy = ConfFile.empty(path)
        stubbed = sections.dup
        names.each do |name|
          settings = ConfFile.deep_merge(stubbed[name]&.settings || {}, data.transform_keys(&:to_s))
          stubbed[name] = Section.new(name, settings, location.lineno, '', location.path)
        end
        copy.instance_variable_set(:@sections, stubbed)
        copy
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

          raise unknown_section(name, location, with_default: names.include?('default')) unless section

          ConfFile.deep_merge(values, section.settings)
        end
      end

      # The location of +key+ in the section that set it last among +names+.
      def location_of(key, names)
        section = section_of(key, names)
        return Location.new(path, 1) unless section

        offset = section.key_line(key.to_s) ||
                 section.text.lines.index { |l| l.match?(/^#{Regexp.escape(key.to_s)}\s*:/) }
        Location.new(section.path, section.line + 1 + offset.to_i)
      end

      # The offset of the first line of +text+ that sets each top-level key
      # ("key: value", the key up to its first colon): a section with N
      # problems is then located in one pass over its lines, where looking
      # for each key in turn made `syskit check` quadratic. A key with a
      # colon in it is looked for in the text (#location_of).
      def self.key_lines(text)
        keys = {}
        text.each_line.with_index do |line, offset|
          key = line[/\A([^\s#:][^:]*?)\s*:/, 1]
          keys[key] ||= offset if key
        end
        keys
      end

      # The section among +names+ whose value of +key+ is the one applied.
      def section_of(key, names)
        names.reverse_each.map { |name| sections[name] }.find { |section| section&.settings&.key?(key) }
      end

      def self.deep_merge(base, override)
        base.merge(override) do |_key, old, new|
          old.is_a?(Hash) && new.is_a?(Hash) ? deep_merge(old, new) : new
        end
      end

      private

      def parse(text)
        current = [{ 'name' => 'default' }, 0, []]
        chunks = []
        text.each_line.with_index(1) do |line, lineno|
          if line.match?(HEADER)
            chunks << current
            current = [header_options(line, lineno), lineno, []]
          else
            current[2] << line
          end
        end
        chunks << current
        chunks.shift if chunks.first[2].all? { |l| l.strip.empty? || l.strip.start_with?('#') } && chunks.size > 1
        # As in Rock, the first section is 'default' when its header has no name.
        chunks.first[0]['name'] ||= 'default'
        declared = {}
        chunks.each { |options, line, lines| add_section(options, line, lines.join, declared) }
      end

      # The options of a header line: name:x merge:true chain:a,b.
      def header_options(line, lineno)
        options = {}
        line.chomp.delete_prefix('---').split(/\s+/).reject(&:empty?).each do |word|
          key, value = word.match(/\A(\w+):(\S*)\z/)&.captures
          raise bad_header_word(word, lineno) unless key && HEADER_OPTIONS.include?(key)

          options[key] = value
        end
        options
      end

      def bad_header_word(word, lineno)
        hint = if word.start_with?('#')
                 'Rock\'s loader takes no comment on a header line: put it on the line above'
               else
                 'a header holds name:section_name, and optionally merge:true and chain:other,sections'
               end
        ConfigurationError.new("'#{word}' on a section header is not one of its options (name:, merge:, chain:)",
                               location: Location.new(path, lineno), hint: hint)
      end

      def add_section(options, line, text, declared)
        location = Location.new(path, line)
        name = header_name(options['name'], location)
        if (other = declared[name])
          first = other.zero? ? 'at the top of the file' : "at line #{other}"
          raise ConfigurationError.new("section '#{name}' is declared twice (first #{first})",
                                       location: location, hint: 'merge the two sections')
        end

        declared[name] = line
        yaml = EmbeddedRuby.expand(text, path, line + 1)
        settings = ConfFile.deep_merge(load_yaml(yaml, line), chained(options['chain'], location))
        settings = ConfFile.deep_merge(sections[name].settings, settings) if merge?(options['merge'], location) &&
                                                                             sections[name]
        sections[name] = Section.new(name, settings, line, text, path)
      end

      def header_name(name, location)
        return name unless name.nil? || name.empty?

        raise ConfigurationError.new('this section header has no name',
                                     location: location, hint: 'write --- name:section_name')
      end

      def merge?(value, location)
        return false if value.nil? || value == 'false'
        return true if value == 'true'

        raise ConfigurationError.new("merge:#{value} on a section header: merge is true or false",
                                     location: location, hint: 'write merge:true, or leave merge out')
      end

      # The sections a chain: option names, merged in order (declared before
      # this header, in this file or in a bundle's).
      def chained(value, location)
        return {} if value.nil?

        value.split(',').reduce({}) do |merged, name|
          section = sections[name]
          unless section
            raise ConfigurationError.new(
              "chain:#{value} names the section '#{name}', which is not declared before this header" \
              "#{Naming.did_you_mean(name, section_names)}",
              location: location, hint: "declare '--- name:#{name}' above this section"
            )
          end

          ConfFile.deep_merge(merged, section.settings)
        end
      end

      def load_yaml(text, header_line)
        # Each section is parsed alone and its lines counted from its
        # header (a prefix of blank lines made parsing a file quadratic in
        # its sections). Symbols are Rock's way of writing enum values
        # (deviceType: :SOCKET).
        values = Psych.safe_load(text, filename: path, aliases: false, permitted_classes: [Symbol]) || {}
        unless values.is_a?(Hash)
          raise ConfigurationError.new('a configuration section must map property names to values',
                                       location: Location.new(path, header_line + 1),
                                       hint: 'write property: value lines')
        end

        check_keys(values, text, header_line)
        values
      rescue Psych::BadAlias
        raise ConfigurationError.new(
          'YAML aliases are not allowed in configuration files (*name repeats an &name value)',
          location: line_of(/(?:^|[\s\[{,:])\*\w/, text, header_line),
          hint: 'write the value out again: configuration files hold plain data'
        )
      rescue Psych::DisallowedClass => e
        raise tag_error(e, text, header_line)
      rescue SystemStackError
        raise ConfigurationError.new('this section is nested too deeply to be read',
                                     location: Location.new(path, header_line + 1),
                                     hint: 'configuration values are property values: a few levels of nesting')
      rescue Psych::SyntaxError => e
        raise ConfigurationError.new("invalid YAML: #{e.problem}",
                                     location: Location.new(path, header_line + e.line),
                                     hint: 'fix the YAML syntax at this line')
      end

      # Psych only says a class was refused: the error points at the first
      # tag of the section and names it when the line shows it. Dates and
      # times are read as such by YAML: they are refused as values.
      def tag_error(error, text, header_line)
        return date_error(error, text, header_line) if error.message.match?(/Date|Time/)

        location = line_of(/!/, text, header_line)
        tag = UserFile.lines(path)[location.lineno - 1].to_s[/!\S+/]
        ConfigurationError.new("YAML tags such as #{tag || 'this one'} are not allowed in configuration files " \
                               "(#{error.message})",
                               location: location,
                               hint: 'configuration files hold plain data: no tags, no Ruby objects')
      end

      # A date or time, named with the property it is given to.
      def date_error(error, text, header_line)
        location = line_of(DATE, text, header_line)
        offset = location.lineno - header_line - 1
        lines = text.lines
        written = lines[offset].to_s
        key = written[/\A\s*(?:-\s+)?([^\s:#][^:#]*?)\s*:/, 1]
        property = lines[0..offset].reverse.map { |l| l[/\A([^\s:#-][^:#]*?)\s*:/, 1] }.compact.first
        value = written[DATE, 1] || 'it'
        what = error.message.include?('Date') ? 'a date' : 'a time'
        where = property && "property '#{property}'#{" (#{key})" if key && key != property}: "
        ConfigurationError.new(
          "#{where}#{value} is read by YAML as #{what}, which is not a property value",
          location: location, hint: "quote it to make it a string: #{key || property || 'key'}: '#{value}'"
        )
      end

      # Top-level keys name properties: anything else (5000:, ~:, [a]:) is
      # refused at its line.
      def check_keys(values, text, header_line)
        values.each_key do |key|
          next if key.is_a?(String)

          offset = text.lines.index do |l|
            l.match?(/^\S/) && !l.start_with?('#') && l.include?(':') && key_line?(l, key)
          end
          raise ConfigurationError.new(
            "#{key.inspect} is not a property name (configuration keys are property names)",
            location: Location.new(path, header_line + 1 + offset.to_i),
            hint: 'write property_name: value, e.g. exposure: 5000'
          )
        end
      end

      def key_line?(line, key)
        written = line.split(':', 2).first.strip
        written == key.to_s || (key.nil? && %w[~ null].include?(written)) || written.start_with?('?', '[', '{')
      end

      # The first line of a section's +text+ matching +marker+.
      def line_of(marker, text, header_line)
        offset = text.lines.index { |l| l.match?(marker) }
        Location.new(path, offset ? header_line + 1 + offset : [header_line, 1].max)
      end

      # +with_default+: whether 'default' is asked for too (else the hint
      # reminds that with_conf replaces it).
      def unknown_section(name, location, with_default: false)
        known = section_names
        file = File.basename(path)
        hint = "add '--- name:#{name}' to #{file}"
        hint += "; with_conf replaces ['default'], so write with_conf('default', '#{name}') to apply both" unless
          with_default
        ConfigurationError.new(
          "no section '#{name}' in #{file}#{Naming.did_you_mean(name, known)} (sections: #{known.join(', ')})",
          location: location, hint: hint
        )
      end
    end
  end
end
