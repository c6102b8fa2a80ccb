# frozen_string_literal: true

module Syskit
  module Robot
    # The values of a device's dsl_attributes (+can_id+, +pgn+: the
    # attributes the configuration modules of its device model and of its
    # bus model declare, see Models::DeviceConfigurationModule#dsl_attribute):
    # set through their filter, read back, and where each was last set.
    # Part of Device (kept in its +dsl_attributes+).
    module DslAttributes
      # Sets a dsl_attribute (see DeviceConfigurationModule#dsl_attribute).
      def set_dsl_attribute(attr, args, filter_method)
        value = if filter_method
                  filter_value(attr, args, filter_method)
                else
                  (args.size == 1 ? args.first : args)
                end
        dsl_attributes[attr] = value
        # The frame that called the attribute's method, if it is the user's
        # (a Location: Ruby's frame objects would keep its backtrace alive,
        # two objects the garbage collector cannot track cheaply, 20,000
        # of them on a 10,000-device robot).
        frame = caller_locations(2, 1).first
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

      # The value the filter block makes of +args+; what it raises says the
      # value is refused (exits and endless recursions are located too).
      def filter_value(attr, args, filter_method)
        # Spelled out for one and two arguments: the splat would copy
        # +args+ on every call (can_id, period... once per device).
        case args.size
        when 1 then send(filter_method, args[0])
        when 2 then send(filter_method, args[0], args[1])
        else send(filter_method, *args)
        end
      rescue Syskit::Error
        raise
      rescue StandardError => e
        raise invalid_attribute(attr, args, filter_method, e)
      rescue Exception => e # rubocop:disable Lint/RescueException -- user code may raise anything
        raise if e.is_a?(SignalException)

        raise UserCode.translate(e, error_class: DeclarationError, context: "#{attr} on #{self}")
      end

      # The parameters of a dsl_attribute's filter block, as users write them.
      def attribute_parameters(attr)
        filter = :"__dsl_attribute_filter_#{attr}"
        return unless respond_to?(filter)

        method(filter).parameters.map { |kind, n| kind == :opt ? "#{n} = ..." : n.to_s }
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
