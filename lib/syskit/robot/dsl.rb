# frozen_string_literal: true

module Syskit
  module Robot
    # The statements of a +robot do ... end+ block.
    class DSL
      def initialize(definition)
        @definition = definition
        @bus = nil
        @comments = DocComment.new
      end

      # Declares a device: +device(Devices::GPS::Ublox::F9, as: 'gps')+.
      # +doc:+, or else the comment block just above, documents it.
      def device(model, as: nil, using: nil, doc: nil, **options)
        declare(MasterDeviceInstance, model, as, using, doc, options, Location.of_caller)
      end

      # Declares a communication bus: +com_bus Devices::Bus::CAN, as: 'can0'+.
      # A block attaches the devices it declares, like +through+.
      def com_bus(model, as: nil, using: nil, doc: nil, **options, &block)
        bus = declare(ComBus, model, as, using, doc, options, Location.of_caller)
        through(bus, &block) if block
        bus
      end

      # Attaches every device declared in the block to the bus +bus_name+.
      def through(bus_name, &block)
        location = Location.of_caller
        bus = @definition.send(:find_bus, bus_name, location)
        unless block
          raise DeclarationError.new("through '#{bus.name}' needs a block",
                                     location: location, hint: "write through '#{bus.name}' do device(...) end")
        end

        previous = @bus
        @bus = bus
        instance_eval(&block)
        bus
      ensure
        @bus = previous
      end

      # A device declared attached to +bus+ (a ComBus): what
      # +bus.device(...)+ declares.
      def device_on(bus, model, **options)
        previous = @bus
        @bus = bus
        device(model, **options)
      ensure
        @bus = previous
      end

      def explain_missing(name)
        ["unknown statement '#{name}' in a robot block#{Naming.did_you_mean(name, %w[device com_bus through])}",
         'robot blocks declare device, com_bus and through'].tap do |m|
          m[1] = "#{name} is a chained call: write it after a device(...) declaration" if chained?(name)
        end
      end

      private

      # The location is found by the statement itself: the user's line is
      # then its caller, the first frame looked at (Location.of_caller).
      def declare(klass, model, name, using, doc, options, location) # rubocop:disable Metrics/ParameterLists
        device = @definition.add_device(klass, model, name, using: using, options: options,
                                                            location: location, bus: @bus)
        doc ||= @comments.above(location)
        doc ? device.doc(doc) : device
      end

      def chained?(name)
        MasterDeviceInstance.public_method_defined?(name)
      end
    end
  end
end
