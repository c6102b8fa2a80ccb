# Types of iodrivers_base.
import_types_from 'base'
accept_unknown_types

struct 'RawPacket' do
  field 'time', '/base/Time'
  field 'data', '/std/vector</uint8_t>'
end
