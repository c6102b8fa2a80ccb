# frozen_string_literal: true

require 'psych'

module Syskit
  class App
    # One of the small YAML files an app's settings are in
    # (config/syskit.yml, Rock's config/app.yml): read with safe YAML, each
    # problem reported at its line with a hint, and the lines settings are
    # written on taken from YAML's own parse, so that a comment or another
    # value that merely contains the same text is never taken for them.
    class SettingsYaml
      # An alias (*name), as YAML writes one.
      ALIAS = /(?:\A|[\s\[{,:-])\*[^\s,\]}]+/
      # What YAML reads as a symbol.
      SYMBOL = /(?:\A|[\s\[{,:-]):\w/

      attr_reader :path, :data

      def initialize(path)
        @path = path
        @text = UserFile.read(path)
        @data = load
      end

      # config/syskit.yml, as messages name it.
      def name
        File.join(File.basename(File.dirname(path)), File.basename(path))
      end

      # The line of the key at the end of +keys+ (a path of mapping keys),
      # else 1.
      def key_line(*keys)
        key, = entry(keys)
        key ? key.start_line + 1 : 1
      end

      # The line of each item of the list at +keys+ (the key's line for
      # items YAML does not place).
      def item_lines(*keys)
        key, value = entry(keys)
        return [] unless value.is_a?(Psych::Nodes::Sequence)

        value.children.map { |item| (item || key).start_line + 1 }
      end

      private

      def load
        Psych.safe_load(@text, filename: path) || {}
      rescue Psych::BadAlias
        raise error("YAML aliases are not allowed in #{name} (*name repeats an &name value)", line_of(ALIAS),
                    'write the value out again: settings are plain names and lists')
      rescue Psych::DisallowedClass => e
        raise disallowed(e)
      rescue Psych::SyntaxError => e
        raise error("invalid YAML in #{name}: #{e.problem}", e.line, 'fix the YAML syntax at this line')
      rescue Psych::Exception => e
        raise error("cannot read #{name}: #{e.message}", 1, 'settings are plain names and lists')
      end

      # A date, a time or a symbol, which settings never are.
      def disallowed(exception)
        what, marker = case exception.message
                       when /Date|Time/ then ['a date or a time', Config::ConfFile::DATE]
                       when /Symbol/ then ['a symbol', SYMBOL]
                       else ['a Ruby object', /!/]
                       end
        error("#{name} holds #{what}, which no setting takes", line_of(marker),
              "settings are plain names and lists: quote the value to make it a string ('...')")
      end

      def error(message, line, hint)
        FileLoadError.new(message, location: Location.new(path, line), hint: hint)
      end

      # The first line that is not a comment matching +marker+, else 1.
      def line_of(marker)
        index = @text.lines.index { |l| !l.lstrip.start_with?('#') && l.match?(marker) }
        index ? index + 1 : 1
      end

      # The key and value nodes of +keys+ in YAML's parse.
      def entry(keys)
        node = Psych.parse(@text)&.root
        keys.reduce(nil) do |_, key|
          return nil unless node.is_a?(Psych::Nodes::Mapping)

          pair = node.children.each_slice(2).find { |k, _| k.is_a?(Psych::Nodes::Scalar) && key_value(k) == key }
          return nil unless pair

          node = pair.last
          pair
        end
      end

      # A key as the loaded data has it: a !!binary key is decoded.
      def key_value(scalar)
        scalar.tag&.end_with?(':binary') ? scalar.value.unpack1('m') : scalar.value
      end
    end
  end
end
