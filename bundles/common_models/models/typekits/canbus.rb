# Types of the canbus driver.
import_types_from 'base'

# One CAN frame.
struct 'Message' do
  field 'time', '/base/Time'
  field 'can_time', '/base/Time'
  field 'can_id', '/uint32_t'
  field 'size', '/uint8_t'
  field 'data', '/uint8_t[8]'
end

# One entry of canbus::Task's watch list: frames with (id & mask) == id go to
# the output port called name.
struct 'Device' do
  field 'name', '/std/string'
  field 'id', '/uint32_t'
  field 'mask', '/uint32_t'
end

enum 'DRIVER_TYPE', %w[SOCKET HICO HICO_PCI EASY_SYNC]

struct 'Statistics' do
  field 'time', '/base/Time'
  field 'msg_tx', '/uint32_t'
  field 'msg_rx', '/uint32_t'
  field 'error_count', '/uint32_t'
end
