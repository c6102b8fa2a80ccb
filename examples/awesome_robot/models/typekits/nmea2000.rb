# Types of the nmea2000 task library.

# One entry of nmea2000::CANTask's device list: the frames of PGN +pgn+ go to
# the output port called +name+.
struct 'Device' do
  field 'name', '/std/string'
  field 'pgn', '/uint32_t'
end

struct 'FluidLevel' do
  field 'instance', '/uint8_t'
  field 'level', '/double'
end
