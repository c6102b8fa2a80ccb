# frozen_string_literal: true

require 'ffi'
require 'syskit/bus/frame'

module Syskit
  module Bus
    # The kernel's CAN frame records (linux/can.h), as FFI structs: what a
    # raw CAN socket reads and writes, and the bridge between Frame values,
    # raw bytes and /canbus/Message values.
    module FrameStructs
      # Conversions shared by both records.
      module Conversions
        # The frame this record holds, received at +time+ (microseconds).
        def to_frame(time: nil)
          can_id = self[:can_id]
          len = self[:len]
          max = self[:data].size
          raise ArgumentError, "a #{self.class.name} cannot hold #{len} data bytes (at most #{max})" if len > max

          data = (can_id & Frame::RTR_FLAG).zero? ? self[:data].to_ptr.get_bytes(0, len) : ''.b
          Frame.new(can_id: can_id, len: len, data: data, time: time, fd_flags: fd_flags)
        end

        # The record as the bytes a socket carries.
        def to_bytes
          to_ptr.get_bytes(0, self.class.size)
        end

        # A /canbus/Message (+type+, e.g. Types.canbus.Message of a loaded
        # app) holding this record. Its can_id keeps the EFF/RTR/ERR flags,
        # as SocketCAN does, so that nothing is lost; time and can_time are
        # both +time+ (microseconds), the time the frame was read.
        def to_message(type, time: 0)
          len = self[:len]
          raise ArgumentError, "a frame of #{len} bytes does not fit in #{type.name} (8 data bytes)" if len > 8

          data = self[:data].to_a.first(8)
          data.fill(0, len) if self[:can_id] & Frame::RTR_FLAG != 0
          stamp = { microseconds: time || 0 }
          type.new(time: stamp, can_time: stamp, can_id: self[:can_id], size: len, data: data)
        end
      end

      # Builders shared by both record classes.
      module Builders
        # The record of +frame+ (a Frame), in its own memory.
        def from_frame(frame)
          record = new
          record[:can_id] = frame.can_id
          record[:len] = frame.len
          record[:data].to_ptr.put_bytes(0, frame.data) unless frame.data.empty?
          record[:flags] = frame.fd_flags if frame.fd? && members.include?(:flags)
          record
        end

        # The record read from +bytes+ (exactly its size).
        def from_bytes(bytes)
          raise ArgumentError, "a #{name} is #{size} bytes, got #{bytes.bytesize}" unless bytes.bytesize == size

          record = new
          record.to_ptr.put_bytes(0, bytes)
          record
        end

        # The record of a /canbus/Message. A can_id without the EFF flag but
        # beyond 11 bits (drivers that drop the flags) is an extended id.
        def from_message(message)
          can_id = message.can_id
          if (can_id & (Frame::EFF_FLAG | Frame::ERR_FLAG)).zero? && can_id & Frame::EFF_MASK > Frame::SFF_MASK
            can_id |= Frame::EFF_FLAG
          end
          rtr = can_id & Frame::RTR_FLAG != 0
          data = rtr ? ''.b : message.data.first(message.size).pack('C*')
          from_frame(Frame.new(can_id: can_id, len: message.size, data: data, time: message.time.microseconds))
        end
      end

      # struct can_frame: 16 bytes, classic CAN (CAN_MTU).
      class CanFrame < FFI::Struct
        include Conversions
        extend Builders

        layout :can_id, :uint32, # id + EFF/RTR/ERR flags
               :len, :uint8,     # payload length (can_dlc)
               :pad, :uint8,
               :res0, :uint8,
               :len8_dlc, :uint8, # DLC 9..15 of an 8-byte frame, when used
               :data, [:uint8, 8]

        def fd_flags
          nil
        end
      end

      # struct canfd_frame: 72 bytes, CAN FD (CANFD_MTU).
      class CanFdFrame < FFI::Struct
        include Conversions
        extend Builders

        layout :can_id, :uint32,
               :len, :uint8,
               :flags, :uint8, # CANFD_BRS, CANFD_ESI, CANFD_FDF
               :res0, :uint8,
               :res1, :uint8,
               :data, [:uint8, 64]

        def fd_flags
          self[:flags]
        end
      end

      CAN_MTU = CanFrame.size
      CANFD_MTU = CanFdFrame.size
      # The record class by size: a raw CAN socket's reads are one or the other.
      RECORDS = { CAN_MTU => CanFrame, CANFD_MTU => CanFdFrame }.freeze

      module_function

      # The record class for +frame+: CAN FD frames need the larger one.
      def for_frame(frame)
        frame.fd? ? CanFdFrame : CanFrame
      end

      # The raw bytes of +frame+, as a CAN socket carries them.
      def encode(frame)
        for_frame(frame).from_frame(frame).to_bytes
      end

      # The Frame of +bytes+ (16 or 72 of them), read at +time+.
      def decode(bytes, time: nil)
        record = RECORDS.fetch(bytes.bytesize) do |size|
          raise ArgumentError,
                "#{size} bytes: a CAN frame record is #{CAN_MTU} (can_frame) or #{CANFD_MTU} (canfd_frame)"
        end
        record.from_bytes(bytes).to_frame(time: time)
      end

      # The /canbus/Message (+type+) of +frame+.
      def to_message(frame, type)
        for_frame(frame).from_frame(frame).to_message(type, time: frame.time)
      end

      # The Frame of a /canbus/Message.
      def from_message(message)
        CanFrame.from_message(message).to_frame(time: message.time.microseconds)
      end
    end
  end
end
