# frozen_string_literal: true

module Syskit
  module Doc
    # What the page of a data service, device or bus model shows, read off
    # the loaded app: its ports, what it provides (with port mappings),
    # what provides it, its drivers, the robots that declare it and, for a
    # bus, its message type, services and attached devices.
    class ModelView
      # A model this one provides; +mappings+ are the ports renamed on the
      # way (their port => ours), identical names left out.
      Provided = Struct.new(:model, :mappings)
      # A task model that provides or drives this model through +services+.
      Implementer = Struct.new(:task_model, :services)
      # The devices of one profile's robot, by name, and for buses the
      # devices attached through each.
      Use = Struct.new(:profile, :devices)

      ROOTS = -> { [Syskit::DataService, Syskit::Device, Syskit::ComBus] }

      attr_reader :model, :catalog

      # (+robot+ and +dot+ are for the views of profiles.)
      def initialize(catalog, model, **_site)
        @catalog = catalog
        @model = model
      end

      def bus?
        model.is_a?(Models::ComBusModel)
      end

      def device?
        model.is_a?(Models::DeviceModel)
      end

      def ports
        model.ports.values
      end

      def provides
        model.parents.filter_map do |parent, mapping|
          next if ROOTS.call.include?(parent)

          Provided.new(parent, mapping.reject { |theirs, ours| theirs == ours })
        end
      end

      # Models of the site that provide this one directly.
      def provided_by
        %i[service device bus].flat_map { |k| catalog.entries(k) }.map(&:object)
                              .select { |m| m.parents.key?(model) }
      end

      # The custom device-model class (the seed's NMEA2000 DeviceModel), if any.
      def model_class
        klass = model.class
        klass unless [Models::DataServiceModel, Models::DeviceModel, Models::ComBusModel].include?(klass)
      end

      # Task models whose services are or provide this model; for a device
      # or bus, its drivers (a bus's include those providing its BusSrv).
      def implementers
        catalog.entries(:task_model).filter_map do |entry|
          task = entry.object
          services = device? ? task.driver_services_for(model) : task.services_fulfilling(model)
          Implementer.new(entry.object, services) unless services.empty?
        end
      end

      # For each profile, its devices whose model is or provides this one.
      def uses
        catalog.entries(:profile).filter_map do |entry|
          devices = entry.object.robot.each_master_device.select { |d| d.model_resolved? && d.model.fullfills?(model) }
          Use.new(entry.object, devices) unless devices.empty?
        end
      end

      # The bus's own services (BusSrv, ClientSrv...), with their ports.
      def bus_services
        return [] unless bus? && model.message_type

        Models::ComBusModel::SERVICES.map { |name| model.const_get(name, false) }
      end

      # Attributes devices attached to a bus of this model get (can_id).
      def attached_device_attributes
        return [] unless bus?

        model.attached_device_configuration_modules.flat_map(&:public_instance_methods).map(&:to_s)
             .reject { |m| m.start_with?('__') }.uniq.sort
      end
    end
  end
end
