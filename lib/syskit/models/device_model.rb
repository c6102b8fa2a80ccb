# frozen_string_literal: true

require 'syskit/models/data_service_model'
require 'syskit/models/device_configuration'

module Syskit
  module Models
    # A device model: what a class of hardware is (+device_type 'F9'+). It
    # provides data services and other devices; drivers declare +driver_for+ it.
    #
    # Subclass it to give a family of devices its own API (the seed's
    # NMEA2000 +pgn+), then pass an instance as +parent:+ to +device_type+.
    class DeviceModel < DataServiceModel
      def self.kind
        'device'
      end

      def initialize(**options)
        super
        @device_configuration = nil
      end

      # Adds the methods defined in the block to every device declared with
      # this model (or a model that provides it).
      def extend_device_configuration(&block)
        Arguments.block(block, statement: 'extend_device_configuration',
                               example: 'extend_device_configuration do dsl_attribute :pgn end')
        @device_configuration ||= DeviceConfigurationModule.new.tap { DataServiceModel.hierarchy_changed }
        @device_configuration.module_eval(&block)
        @device_configuration
      end

      # The configuration modules of this model and the devices it provides,
      # the most generic first so that specific models override.
      def device_configuration_modules
        hierarchy_view(:device_configuration_modules) do
          fullfilled_models.reverse.filter_map do |m|
            m.instance_variable_get(:@device_configuration) if m.is_a?(DeviceModel)
          end
        end
      end

      private

      def check_provides(model, location)
        super
        return unless model.is_a?(ComBusModel) && !is_a?(ComBusModel)

        raise DeclarationError.new(
          "#{self} is a device and cannot provide the communication bus #{model}",
          location: location, hint: 'declare buses with com_bus_type; devices are attached to them with through'
        )
      end
    end
  end
end
