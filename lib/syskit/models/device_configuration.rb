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
      def dsl_attribute(name = nil, &filter)
        attr = Arguments.name(name, statement: 'dsl_attribute', what: 'an attribute name', pattern: Arguments::METHOD_NAME,
                                    example: 'dsl_attribute :can_id do |id, mask = id| ... end').to_sym
        filter_method = :"__dsl_attribute_filter_#{attr}"
        # define_method gives the filter a method's strict arity.
        define_method(filter_method, &filter) if filter
        if filter && two_positional_parameters?(filter_method)
          define_pair_attribute(attr, filter_method)
        else
          define_list_attribute(attr, filter ? filter_method : nil)
        end
        (@dsl_attribute_names ||= []) << attr
        attr
      end

      # The attributes declared with dsl_attribute, and the parameters of
      # each (as Method#parameters; [[:rest]] when it has no block).
      def dsl_attribute_parameters
        (@dsl_attribute_names || []).to_h do |attr|
          filter = :"__dsl_attribute_filter_#{attr}"
          [attr, method_defined?(filter) ? instance_method(filter).parameters : [[:rest]]]
        end
      end

      # The attribute's method for a filter of two positional parameters,
      # as CAN's +can_id(id, mask = id)+ (a robot calls it once per device):
      # taking them as they are rather than as a list saves the list. Ruby
      # refuses a third argument itself ("given 3, expected 0..2"), the
      # filter a missing one.
      def define_pair_attribute(attr, filter_method)
        # Ifs rather than an early return: a return from the block of
        # define_method costs an object at each read (generation reads an
        # attribute per device).
        none = Robot::DslAttributes::NONE
        define_method(attr) do |first = none, second = none|
          if first.equal?(none)
            read_attribute(attr, dsl_attributes[attr])
          else
            set_dsl_attribute_pair(attr, first, second, filter_method)
          end
        end
      end

      # The attribute's method for any other filter, or none.
      def define_list_attribute(attr, filter_method)
        define_method(attr) do |*args|
          if args.empty?
            read_attribute(attr, dsl_attributes[attr])
          else
            set_dsl_attribute(attr, args, filter_method)
          end
        end
      end

      def two_positional_parameters?(filter_method)
        parameters = instance_method(filter_method).parameters
        parameters.size == 2 && parameters.all? { |kind, _| %i[req opt].include?(kind) }
      end

      # What the attribute +name+ takes, as Method#parameters (see
      # RefusedCall): its filter's parameters; nil for other methods.
      def parameters_of(name)
        dsl_attribute_parameters[name] if @dsl_attribute_names&.include?(name)
      end

      # Whether devices already have a method +name+: a public one, or a
      # private one of the gem's device classes or of Ruby itself (raise,
      # format...), on which their own code relies. Private methods other
      # libraries add to every object (minitest's describe) do not count.
      def self.device_method?(name)
        return true if Robot::ComBus.method_defined?(name)
        return false unless Robot::ComBus.private_method_defined?(name)

        path, = Robot::ComBus.instance_method(name).source_location
        path.nil? || path.start_with?('<internal:', Location::GEM_LIB)
      end

      # Methods defined here (by dsl_attribute or def) become methods of
      # devices: one named like a method devices already have (name,
      # with_conf, ...) would replace it and break the device.
      def method_added(name)
        super
        return unless DeviceConfigurationModule.device_method?(name)

        remove_method(name)
        raise DeclarationError.new(
          "'#{name}' is a method of every device: defining it here would replace it",
          location: Location.of_caller, hint: "give the attribute another name, e.g. #{name}_value"
        )
      end
    end
  end
end
