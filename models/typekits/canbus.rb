# Types of Rock's canbus driver package.
import_types_from 'base'

# One CAN frame.
struct 'Message' do
  field 'time', '/base/Time'
  field 'can_time', '/base/Time'
  field 'can_id', '/uint32_t'
  field 'size', '/uint8_t'
  field 'data', '/uint8_t[8]'
end

# A port canbus::Task creates at configure time from its outputPorts
# property: the frames with (id & mask) == id.
struct 'CanOutputPort' do
  field 'ports_name', '/std/string'
  field 'mask', '/uint32_t'
  field 'id', '/uint32_t'
end

enum 'DRIVER_TYPE', %w[SOCKET HICO HICO_PCI EASY_SYNC]

struct 'Statistics' do
  field 'time', '/base/Time'
  field 'msg_tx', '/uint64_t'
  field 'msg_rx', '/uint64_t'
  field 'tx', '/uint64_t'
  field 'rx', '/uint64_t'
  field 'error_count', '/uint64_t'
end
