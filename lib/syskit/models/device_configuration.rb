# frozen_string_literal: true

module Syskit
  module Models
    # The module +extend_device_configuration+ and
    # +extend_attached_device_configuration+ blocks are evaluated in: methods
    # defined there become methods of device declarations, and +dsl_attribute+
    # defines chainable attributes such as CAN's +can_id+.
    class DeviceConfigurationModule < Module
      # Defines +name+ on devices:
      # - without arguments, returns the value (nil when never set)
      # - with arguments, stores the block's result (or the single argument
      #   when there is no block) and returns the device, for chaining.
      # The block may raise to reject the arguments; the error then points at
      # the user's call.
      def dsl_attribute(name, &filter)
        attr = name.to_sym
        filter_method = :"__dsl_attribute_filter_#{attr}"
        # define_method gives the filter a method's strict arity.
        define_method(filter_method, &filter) if filter
        define_method(attr) do |*args|
          return dsl_attributes[attr] if args.empty?

          set_dsl_attribute(attr, args, filter ? filter_method : nil)
        end
        attr
      end
    end
  end
end
