# frozen_string_literal: true

module Syskit
  module Robot
    # The values of a device's dsl_attributes (+can_id+, +pgn+: the
    # attributes the configuration modules of its device model and of its
    # bus model declare, see Models::DeviceConfigurationModule#dsl_attribute):
    # set through their filter, read back, and where each was last set.
    # Part of Device (kept in its +dsl_attributes+).
    module DslAttributes
      # What an attribute method's second parameter is when not given.
      NONE = Object.new.freeze

      # Sets a dsl_attribute (see DeviceConfigurationModule#dsl_attribute)
      # from the list of its arguments.
      def set_dsl_attribute(attr, args, filter_method)
        # Spelled out for one and two arguments: the splat would copy
        # +args+ on every call.
        value = if !filter_method then (args.size == 1 ? args.first : args)
                elsif args.size == 1 then filter_value(attr, filter_method, args[0])
                elsif args.size == 2 then filter_value(attr, filter_method, args[0], args[1])
                else filter_value(attr, filter_method, nil, nil, args)
                end
        store_dsl_attribute(attr, value, caller_locations(2, 1).first)
      end

      # Sets a dsl_attribute whose filter takes two positional parameters
      # from its one or two arguments (+second+ NONE when not given).
      def set_dsl_attribute_pair(attr, first, second, filter_method)
        value = filter_value(attr, filter_method, first, second)
        store_dsl_attribute(attr, value, caller_locations(2, 1).first)
      end

      # Keeps +value+ and +frame+, the frame that called the attribute's
      # method, if it is the user's (as a Location: Ruby's frame objects
      # would keep its backtrace alive, two objects the garbage collector
      # cannot track cheaply, 20,000 of them on a 10,000-device robot).
      def store_dsl_attribute(attr, value, frame)
        dsl_attributes[attr] = value
        location = Location.user_frame?(frame) ? Location.from(frame) : nil
        # Usually chained on the device's own line (the same Location, see
        # Location.from): nothing to keep then, the device's location is
        # the answer.
        if location.nil? || location.equal?(declared_at)
          @dsl_attribute_frames&.delete(attr)
        else
          (@dsl_attribute_frames ||= {})[attr] = location
        end
        self
      end

      # Where the attribute +attr+ was last set (the user's +.can_id(...)+
      # line), for the checks that judge its value; else where the device
      # is declared.
      def dsl_attribute_location(attr)
        @dsl_attribute_frames&.[](attr) || declared_at
      end

      # The value of an attribute called without arguments. In the robot
      # block that declares the device, reading an attribute never set is a
      # setting whose arguments were forgotten (+.can_id.with_conf(...)+
      # would call with_conf on nil): refused there.
      def read_attribute(attr, value, expected = nil)
        return value unless value.nil? && robot.declaring?

        params = attribute_parameters(attr)
        call = params ? ".#{attr}(#{params.join(', ')})" : ".#{attr}(...)"
        raise DeclarationError.new(
          "#{attr} without arguments reads the #{attr} of #{self}, which is not set",
          location: Location.of_caller, hint: "to set it, give #{expected || 'its arguments'}: #{call}"
        )
      end

      private

      # The value the filter block makes of the arguments: +first+, and
      # +second+ unless NONE, or the list +more+ when there are more; what
      # it raises says the value is refused (exits and endless recursions
      # are located too).
      def filter_value(attr, filter_method, first, second = NONE, more = nil)
        if more then send(filter_method, *more)
        elsif second.equal?(NONE) then send(filter_method, first)
        else send(filter_method, first, second)
        end
      rescue Syskit::Error
        raise
      rescue StandardError => e
        raise invalid_attribute(attr, more || (second.equal?(NONE) ? [first] : [first, second]), filter_method, e)
      rescue Exception => e # rubocop:disable Lint/RescueException -- user code may raise anything
        raise if e.is_a?(SignalException)

        raise UserCode.translate(e, error_class: DeclarationError, context: "#{attr} on #{self}")
      end

      # The parameters of a dsl_attribute's filter block, as users write them.
      def attribute_parameters(attr)
        filter = :"__dsl_attribute_filter_#{attr}"
        return unless respond_to?(filter)

        Arguments.as_written(method(filter).parameters)
      end

      def invalid_attribute(attr, args, filter_method, error)
        params = attribute_parameters(attr) if filter_method
        (error.is_a?(ArgumentError) ? InvalidArgument : DeclarationError).new(
          "#{attr}(#{args.map(&:inspect).join(', ')}) on #{self}: #{error.message}",
          location: Location.of_caller,
          hint: params ? "#{attr} takes (#{params.join(', ')})" : "check the arguments of #{attr}"
        )
      end
    end
  end
end
