# frozen_string_literal: true

module Syskit
  module Config
    # Numbers as Rock's configuration files may write them for numeric
    # fields: with units, converted to SI, and with a rounding mode for
    # integers.
    #
    #   angle: 2.deg          # 0.0349...
    #   timeout: 150.ms       # 0.15
    #   area: 3.cm^2          # 0.0003
    #   ticks: 2.5.round      # 3, for an integer field
    #
    # Only fields whose type is known to be numeric are read this way: a
    # string field keeps "2.deg", and so does a value of an opaque type.
    # A number with a fractional part given to an integer field is rounded
    # down, with a warning, unless it names its rounding (.round, .floor,
    # .ceil).
    class NumbersWithUnits
      # Units, in SI.
      UNITS = { 'm' => 1, 's' => 1, 'N' => 1, 'Pa' => 1, 'g' => 1e-3, 'bar' => 1e5, 'deg' => Math::PI / 180 }.freeze
      # Prefixes a unit may take (km, ms, mus for microseconds).
      PREFIXES = { 'p' => 1e-12, 'n' => 1e-9, 'mu' => 1e-6, 'm' => 1e-3, 'c' => 1e-2, 'd' => 1e-1,
                   'k' => 1e3, 'M' => 1e6 }.freeze
      ROUNDING = %w[round floor ceil].freeze
      NUMBER = /\A([+-]?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?)((?:\.[A-Za-z]+(?:\^-?\d+)?)*)\z/

      # +warn+ is called with a message and a hint for what Rock's loader
      # only warns about.
      def initialize(&warn)
        @warn = warn
      end

      # +value+ read for +type+: numbers written as text converted where
      # the type says a number goes, at any depth.
      def convert(type, value)
        case type
        when Types::IntegerType, Types::FloatType then number(type, value)
        when Types::ContainerType then value.is_a?(Array) ? value.map { |v| convert(type.element, v) } : value
        when Types::StructType then value.is_a?(Hash) ? fields(type, value) : value
        else value
        end
      end

      private

      def fields(type, hash)
        hash.to_h do |name, v|
          field = type.fields[name.to_s]
          [name, field ? convert(field, v) : v]
        end
      end

      def number(type, value)
        rounding = nil
        value, rounding = parse(value) if value.is_a?(String)
        return value unless type.is_a?(Types::IntegerType) && value.is_a?(Float) && value.finite?

        round(value, rounding)
      end

      # "2.5.deg" as [0.0436..., nil]; "7" as [7, nil]; "2.5.ceil" as [2.5, 'ceil'].
      # Text that does not start as a number is left to the type to refuse.
      def parse(text)
        return [text, nil] unless text.match?(/\A\s*[+-]?\d/)

        match = NUMBER.match(text.strip)
        raise Types::ValueError, "#{text.inspect} is not a number followed by units (2.5, 2.deg, 150.ms)" unless
          match

        digits, suffixes = match.captures
        number = digits.match?(/[.eE]/) ? Float(digits) : Integer(digits, 10)
        rounding = nil
        scale = suffixes.scan(/\.([A-Za-z]+)(?:\^(-?\d+))?/).reduce(1) do |product, (unit, power)|
          next product.tap { rounding = unit } if ROUNDING.include?(unit) && power.nil?

          product * (unit_scale(unit, text)**Integer(power || '1', 10))
        end
        [scale == 1 ? number : number * scale, rounding]
      end

      def unit_scale(unit, text)
        return UNITS[unit] if UNITS.key?(unit)

        prefix, scale = PREFIXES.find { |p, _| unit.start_with?(p) && UNITS.key?(unit.delete_prefix(p)) }
        return scale * UNITS.fetch(unit.delete_prefix(prefix)) if prefix

        raise Types::ValueError, "#{text.inspect}: '#{unit}' is not a unit this loader knows " \
                                 "(#{UNITS.keys.join(', ')}, with a prefix among #{PREFIXES.keys.join(', ')})"
      end

      def round(value, rounding)
        return value.public_send(rounding) if rounding
        return value.to_i if value == value.floor

        @warn&.call("#{value} given to an integer field is rounded down to #{value.floor}",
                    'append the rounding you want to the value: .round, .floor or .ceil (2.5.round)')
        value.floor
      end
    end
  end
end
