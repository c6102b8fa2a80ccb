# frozen_string_literal: true

module Syskit
  module Compat
    # Roby's +Conf+: settings that robot configurations write
    # (+Conf.gazebo.use_sim_time = false+) and configure methods read
    # (+Conf.gazebo.use_sim_time?+). Any name is a setting, and a setting
    # never written is a group of settings (so +Conf.a.b = 1+ works);
    # +name?+ says whether it was written with a true value.
    #
    # The names are the users', so this is a method_missing, kept here at
    # the edge with the other constructs of Rock's runtime (see Compat).
    class ConfStruct
      def initialize(path = 'Conf')
        @path = path
        @values = {}
      end

      def to_s
        @path
      end
      alias inspect to_s

      # Settings written so far, by name.
      def to_h
        @values.transform_values { |v| v.is_a?(ConfStruct) ? v.to_h : v }
      end

      private

      def method_missing(name, *args)
        key = name.to_s
        return @values[key.delete_suffix('=')] = args.first if key.end_with?('=') && args.size == 1
        return super unless args.empty?
        return truthy?(key.delete_suffix('?')) if key.end_with?('?')

        @values.fetch(key) { @values[key] = ConfStruct.new("#{@path}.#{key}") }
      end

      def respond_to_missing?(name, _include_private = false)
        @values.key?(name.to_s.delete_suffix('?'))
      end

      def truthy?(key)
        value = @values[key]
        value.is_a?(ConfStruct) ? false : !!value
      end
    end
  end
end
