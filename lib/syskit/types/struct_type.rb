# frozen_string_literal: true

require 'syskit/types/type'

module Syskit
  module Types
    # A structure with named, typed fields, declared in a typekit file:
    #
    #   struct 'Device' do
    #     field 'name', '/std/string'
    #     field 'id', '/uint32_t'
    #   end
    #
    # Its values are instances of {#value_class}, built positionally
    # (+Types.my_bus.Device.new('gps', 1, 2)+) or with keywords.
    class StructType < Type
      attr_reader :fields, :value_class

      def initialize(name, fields)
        super(name)
        @fields = fields.freeze
        @value_class = StructValue.for(self)
      end

      def new(...)
        value_class.new(...)
      end

      def field_names
        fields.keys
      end

      def zero
        value_class.new
      end

      def from_ruby(value)
        case value
        when value_class then value
        when StructValue
          raise ValueError, "expected a #{name}, got a #{value.class.type.name}"
        when Hash then from_hash(value)
        else
          converted = converted_from_ruby(value)
          return from_ruby(converted) if converted

          mismatch(value, "a #{name} or a hash of its fields (#{field_names.join(', ')})")
        end
      end

      # Values of +ruby_class+ stand for values of this type: +block+,
      # evaluated on the type, makes one from them (see
      # TypekitLoader::DSL#convert_from_ruby).
      def convert_from_ruby(ruby_class, block)
        (@ruby_conversions ||= []) << [ruby_class, block]
        self
      end

      def to_plain(value)
        plain = {}
        fields.each { |fname, ftype| plain[fname] = ftype.to_plain(value[fname]) }
        plain
      end

      private

      # +value+ converted by the conversion of its Ruby class, or nil.
      def converted_from_ruby(value)
        _, block = @ruby_conversions&.find { |klass, _| value.is_a?(klass) }
        instance_exec(value, &block) if block
      end

      def from_hash(hash)
        unknown = hash.keys.map(&:to_s) - field_names
        unless unknown.empty?
          raise ValueError, "#{name} has no field '#{unknown.first}'" \
                            "#{Naming.did_you_mean(unknown.first, field_names)}; " \
                            "its fields are #{field_names.join(', ')}"
        end

        value_class.new(**hash.transform_keys(&:to_sym))
      end
    end

    # Base class of the Ruby classes that hold struct values.
    class StructValue
      # Methods a field must not hide, or Ruby itself stops working on the value.
      RESERVED = %i[hash class object_id send public_send freeze dup clone == eql? inspect to_h].freeze

      class << self
        attr_reader :type

        # A new value class for +type+, with a reader and writer per field.
        def for(type)
          klass = Class.new(self)
          klass.instance_variable_set(:@type, type)
          type.fields.each_key do |fname|
            next if RESERVED.include?(fname.to_sym)

            klass.define_method(fname) { self[fname] }
            klass.define_method("#{fname}=") { |v| self[fname] = v }
          end
          klass
        end

        def name
          type&.name
        end

        alias to_s name
        alias inspect name
      end

      def initialize(*args, **kwargs)
        fields = self.class.type.fields
        if args.size > fields.size
          raise ArgumentError, "#{self.class.type.name} has #{fields.size} fields " \
                               "(#{fields.keys.join(', ')}), got #{args.size} values"
        end

        @values = fields.transform_values(&:zero)
        names = fields.keys
        args.each_with_index { |v, i| self[names[i]] = v }
        kwargs.each { |k, v| self[k] = v }
      end

      def [](fname)
        @values.fetch(check_field(fname))
      end

      def []=(fname, value)
        fname = check_field(fname)
        @values[fname] = self.class.type.fields[fname].from_ruby(value)
      rescue ValueError => e
        raise ArgumentError, "#{self.class.type.name}.#{fname}: #{e.message}"
      end

      def to_h
        @values.dup
      end

      def ==(other)
        other.class == self.class && other.to_h == to_h
      end
      alias eql? ==

      def hash
        [self.class, @values].hash
      end

      def inspect
        "#<#{self.class.type.name} #{@values.map { |k, v| "#{k}=#{v.inspect}" }.join(' ')}>"
      end
      alias to_s inspect

      private

      def check_field(fname)
        fname = fname.to_s
        return fname if @values.key?(fname)

        names = @values.keys
        raise ArgumentError, "#{self.class.type.name} has no field '#{fname}'" \
                             "#{Naming.did_you_mean(fname, names)}; its fields are #{names.join(', ')}"
      end
    end
  end
end
