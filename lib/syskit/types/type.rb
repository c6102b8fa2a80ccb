# frozen_string_literal: true

module Syskit
  module Types
    # Raised by a type when a value does not fit it. Callers turn it into a
    # located Syskit::TypeError (they know the property, file and line).
    class ValueError < StandardError; end

    # A named data type, such as +/canbus/Message+ or +/std/string+.
    #
    # Types convert values given by users (Ruby values or plain data read from
    # YAML) into their canonical Ruby form with {#from_ruby}, and back into
    # plain data (for plans and JSON) with {#to_plain}.
    class Type
      attr_reader :name

      def initialize(name)
        @name = name
      end

      def to_s
        name
      end

      def inspect
        "#<#{self.class.name.split('::').last} #{name}>"
      end

      # The value a property of this type has when nothing sets it.
      def zero
        nil
      end

      def from_ruby(value)
        value
      end

      def to_plain(value)
        value
      end

      # Whether values of this type are opaque to the gem (declared in C++
      # headers it cannot read).
      def opaque?
        false
      end

      private

      def mismatch(value, expected)
        raise ValueError, "expected #{expected} for #{name}, got #{value.inspect}"
      end

      # +value+ as a Float. NaN and the infinities are values as in
      # Typelib (Rock's configuration files write .nan for "unknown"): the
      # plan's JSON writes them as NaN and Infinity (see Render::JSON).
      def float(value)
        mismatch(value, 'a number') unless value.is_a?(Numeric) && value.real?
        value.to_f
      end

      # +value+ (a String or Symbol) as UTF-8 text: plans are UTF-8, so
      # binary data (a YAML !!binary, bytes read from a file) and invalid
      # bytes are refused where they are set; text in another encoding is
      # converted.
      def text(value)
        str = value.is_a?(Symbol) ? value.name : value
        return str if str.encoding == Encoding::UTF_8 && str.valid_encoding?

        utf8 = str.encoding == Encoding::BINARY ? str.dup.force_encoding(Encoding::UTF_8) : str.encode(Encoding::UTF_8)
        return utf8 if utf8.valid_encoding?

        not_text(str)
      rescue EncodingError
        not_text(str)
      end

      def not_text(str)
        what = str.encoding == Encoding::BINARY ? 'binary data' : "bytes that are not valid #{str.encoding}"
        excerpt = str.byteslice(0, 24).inspect
        raise ValueError, "expected UTF-8 text for #{name}, got #{what} (#{excerpt}#{'...' if str.bytesize > 24})"
      end
    end

    # Integer types: int, /int32_t, /uint8_t, ...
    class IntegerType < Type
      attr_reader :range

      def initialize(name, bits:, signed:)
        super(name)
        @range = signed ? (-(2**(bits - 1))...(2**(bits - 1))) : (0...(2**bits))
      end

      def zero
        0
      end

      def from_ruby(value)
        mismatch(value, 'an integer') unless value.is_a?(Integer)
        raise ValueError, "#{value} is out of range for #{name} (#{range.min}..#{range.max})" unless range.cover?(value)

        value
      end
    end

    # Floating-point types: double, float.
    class FloatType < Type
      def zero
        0.0
      end

      def from_ruby(value)
        float(value)
      end
    end

    # A floating-point field whose value may be unknown, as Rock writes it:
    # NaN (base::unknown<double>()), which it is when nothing sets it (and
    # which a plan shows as NaN).
    class MaybeUnknownFloat < FloatType
      def zero
        Float::NAN
      end

      def from_ruby(value)
        return Float::NAN if value.nil? || (value.is_a?(Float) && value.nan?)

        super
      end
    end

    # bool
    class BoolType < Type
      def zero
        false
      end

      # 0 and 1 are false and true, as C++ and Typelib convert them (oroGen
      # specs write property defaults that way).
      def from_ruby(value)
        return value == 1 if [0, 1].include?(value)

        mismatch(value, 'true or false') unless [true, false].include?(value)
        value
      end
    end

    # /std/string
    class StringType < Type
      def zero
        ''
      end

      def from_ruby(value)
        mismatch(value, 'a string') unless value.is_a?(String) || value.is_a?(Symbol)
        text(value.is_a?(Symbol) ? value.to_s : value)
      end
    end

    # An enumeration; values are symbols, written as strings or symbols.
    class EnumType < Type
      attr_reader :values

      def initialize(name, values)
        super(name)
        @values = values.map(&:to_sym).freeze
      end

      def zero
        values.first
      end

      def from_ruby(value)
        sym = (value.is_a?(String) ? text(value) : value).to_sym if value.respond_to?(:to_sym)
        return sym if values.include?(sym)

        raise ValueError, "#{value.inspect} is not a value of #{name} (#{values.join(', ')})"
      end

      def to_plain(value)
        value.to_s
      end
    end

    # /std/vector<T>: values are Ruby arrays of T.
    class ContainerType < Type
      attr_reader :element

      def initialize(name, element)
        super(name)
        @element = element
      end

      def zero
        []
      end

      def from_ruby(value)
        mismatch(value, 'an array') unless value.is_a?(Array)
        value.each_with_index.map do |v, i|
          element.from_ruby(v)
        rescue ValueError => e
          raise ValueError, "element #{i}: #{e.message}"
        end
      end

      def to_plain(value)
        value.map { |v| element.to_plain(v) }
      end
    end

    # T[N]: a fixed-size array.
    class ArrayType < ContainerType
      attr_reader :size

      def initialize(name, element, size)
        super(name, element)
        @size = size
      end

      def zero
        Array.new(size) { element.zero }
      end

      def from_ruby(value)
        values = super
        raise ValueError, "#{name} holds exactly #{size} elements, got #{values.size}" unless values.size == size

        values
      end
    end

    # A type declared in a C/C++ header the gem cannot read: any plain value
    # (hash, array, string, number, boolean) is accepted, as long as a plan
    # can hold it (numbers, UTF-8 text, at any depth).
    class OpaqueType < Type
      def opaque?
        true
      end

      # A value of an opaque type is plain data: +Types.base.Pose.new(position:
      # [1, 2, 3])+ is the hash of its fields.
      def new(**fields)
        from_ruby(fields.transform_keys(&:to_s))
      end

      def from_ruby(value)
        case value
        when Hash then value.to_h { |k, v| [from_ruby(k), from_ruby(v)] }
        when Array then value.map { |v| from_ruby(v) }
        when String then text(value)
        when Symbol then text(value).to_sym
        # A value of Rock's Ruby bindings (Eigen::Vector3.new(1, 2, 3) for
        # a /base/Vector3d), modelled or not, is kept as it is.
        when Integer, true, false, nil, Compat::NotModelledValue, Compat::Eigen::Value then value
        when Numeric then float(value)
        else mismatch(value, 'plain data (hash, array, string, number)')
        end
      end

      def to_plain(value)
        case value
        when Hash then value.to_h { |k, v| [to_plain(k), to_plain(v)] }
        when Array then value.map { |v| to_plain(v) }
        when Compat::NotModelledValue then value.to_s
        when Compat::Eigen::Value then value.to_a
        else value
        end
      end
    end
  end
end
