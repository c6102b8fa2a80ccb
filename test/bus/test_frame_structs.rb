# frozen_string_literal: true

require 'helper'
require 'syskit/bus/frame_structs'

module Syskit
  module Bus
    # The kernel's frame records as FFI structs, and their conversions.
    class TestFrameStructs < Minitest::Test
      def test_the_records_have_the_kernel_layout
        assert_equal 16, FrameStructs::CanFrame.size
        assert_equal 72, FrameStructs::CanFdFrame.size
        assert_equal({ can_id: 0, len: 4, len8_dlc: 7, data: 8 },
                     %i[can_id len len8_dlc data].to_h { |f| [f, FrameStructs::CanFrame.offset_of(f)] })
        assert_equal({ can_id: 0, len: 4, flags: 5, data: 8 },
                     %i[can_id len flags data].to_h { |f| [f, FrameStructs::CanFdFrame.offset_of(f)] })
      end

      def test_a_classic_frame_as_bytes
        frame = Frame.new(can_id: 0x123, data: "\xDE\xAD".b)
        bytes = FrameStructs.encode(frame)
        assert_equal [0x123, 2, "\xDE\xAD".b + ("\0" * 6)], bytes.unpack('L<Cx3a8')
        assert_equal frame, FrameStructs.decode(bytes)
      end

      def test_an_extended_fd_frame_as_bytes
        frame = Frame.new(can_id: 0x1234_5678 | Frame::EFF_FLAG, data: (1..12).to_a.pack('C*'), fd_flags: 1, time: 7)
        bytes = FrameStructs.encode(frame)
        assert_equal 72, bytes.bytesize
        assert_equal [0x9234_5678, 12, 1], bytes.unpack('L<CC')
        decoded = FrameStructs.decode(bytes, time: 7)
        assert_equal frame, decoded
        assert decoded.extended?
        assert decoded.fd?
      end

      def test_an_rtr_frame_keeps_its_requested_length_without_data
        frame = Frame.new(can_id: 0x123 | Frame::RTR_FLAG, len: 3)
        decoded = FrameStructs.decode(FrameStructs.encode(frame))
        assert decoded.rtr?
        assert_equal [3, ''.b], [decoded.len, decoded.data]
      end

      def test_records_of_another_size_are_refused
        error = assert_raises(ArgumentError) { FrameStructs.decode("\0" * 20) }
        assert_match(/20 bytes: a CAN frame record is 16 \(can_frame\) or 72 \(canfd_frame\)/, error.message)
        bad = [0x123, 9].pack('L<Cx3') + ("\0" * 8)
        assert_raises(ArgumentError) { FrameStructs.decode(bad) }
      end

      def message_type
        load_app(File.join(GEM_ROOT, 'examples', 'awesome_robot'))
        ::Types.canbus.Message
      end

      def test_frames_to_and_from_canbus_messages
        type = message_type
        frame = Frame.new(can_id: 0x1234 | Frame::EFF_FLAG, data: "\x08\x75".b, time: 1_436_509_053_252_905)
        message = FrameStructs.to_message(frame, type)
        stamp = { microseconds: 1_436_509_053_252_905 }
        expected = type.new(time: stamp, can_time: stamp, can_id: 0x8000_1234, size: 2,
                            data: [8, 0x75, 0, 0, 0, 0, 0, 0])
        assert_equal expected, message
        assert_equal frame, FrameStructs.from_message(message)
      end

      def test_the_struct_itself_converts_messages
        type = message_type
        record = FrameStructs::CanFrame.from_message(type.new(can_id: 0x300, size: 1, data: [7, 0, 0, 0, 0, 0, 0, 0]))
        assert_equal [0x300, 1, 7], [record[:can_id], record[:len], record[:data][0]]
        assert_equal 0x300, record.to_message(type)[:can_id]
      end

      def test_a_message_without_flags_and_an_id_beyond_11_bits_is_extended
        frame = FrameStructs.from_message(message_type.new(can_id: 0x1F21123, size: 0))
        assert frame.extended?
        assert_equal 0x1F21123, frame.id
      end

      def test_an_fd_frame_longer_than_8_bytes_is_no_message
        frame = Frame.new(can_id: 0x123, data: "\0".b * 12, fd_flags: 0)
        error = assert_raises(ArgumentError) { FrameStructs.to_message(frame, message_type) }
        assert_match %r{12 bytes does not fit in /canbus/Message}, error.message
      end
    end
  end
end
