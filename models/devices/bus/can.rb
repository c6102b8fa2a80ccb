module CommonModels
  module Devices
    module Bus
      import_types_from 'canbus'

      # Controller Area Network. Devices attached to a CAN bus declare the
      # frames they receive with can_id(id, mask): a frame goes to a device
      # when (frame_id & mask) == id. The pair is stored as given; a filter
      # no frame can pass is a `syskit check` warning.
      com_bus_type 'CAN', message_type: '/canbus/Message' do
        extend_attached_device_configuration do
          dsl_attribute :can_id do |id, mask = id|
            Syskit::CAN.filter_value(id, mask)
          end
        end
      end
    end
  end
end
