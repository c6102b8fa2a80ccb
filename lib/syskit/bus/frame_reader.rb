# frozen_string_literal: true

require 'syskit/bus/errors'
require 'syskit/bus/frame_structs'

module Syskit
  module Bus
    # Reads CAN frame records (struct can_frame, 16 bytes; struct
    # canfd_frame, 72 bytes) from any IO and stamps them with the time they
    # were read.
    #
    # On a message-oriented IO (a raw CAN socket, a UNIX datagram or
    # seqpacket socket) each read returns one record, whose size tells its
    # kind: the default. On a byte stream (a pipe, a file, a UNIX stream
    # socket) records cannot be told apart, so they all have the size given
    # as +mtu+ (FrameStructs::CAN_MTU or CANFD_MTU).
    class FrameReader
      # Microseconds since the epoch, the frames' time stamps.
      CLOCK = -> { Process.clock_gettime(Process::CLOCK_REALTIME, :microsecond) }

      attr_reader :io

      def initialize(io, mtu: nil, clock: CLOCK)
        unless mtu.nil? || [FrameStructs::CAN_MTU, FrameStructs::CANFD_MTU].include?(mtu)
          raise ArgumentError, "mtu must be #{FrameStructs::CAN_MTU} or #{FrameStructs::CANFD_MTU}, got #{mtu}"
        end

        @io = io
        @mtu = mtu
        @clock = clock
      end

      # The next frame, waiting for it; nil at the end of the input.
      def read
        bytes = @mtu ? @io.read(@mtu) : @io.readpartial(FrameStructs::CANFD_MTU)
        bytes && decode(bytes)
      rescue EOFError
        nil
      end

      # The next frame if one is there, :wait_readable if none is yet, nil
      # at the end of the input.
      def read_nonblock
        bytes = @io.read_nonblock(@mtu || FrameStructs::CANFD_MTU, exception: false)
        return bytes if bytes.nil? || bytes == :wait_readable
        return decode(bytes) if @mtu.nil? || bytes.bytesize == @mtu

        # A stream record split across reads: wait for the rest of it.
        rest = @io.read(@mtu - bytes.bytesize)
        decode(rest ? bytes + rest : bytes)
      end

      # Yields every frame until the end of the input.
      def each
        return enum_for(:each) unless block_given?

        while (frame = read)
          yield frame
        end
      end

      private

      def decode(bytes)
        FrameStructs.decode(bytes, time: @clock.call)
      rescue ArgumentError => e
        hint = @mtu ? 'the stream ended in the middle of a record' : 'read CAN frames from a raw CAN socket'
        raise InterfaceError.new("cannot read a CAN frame from #{@io.inspect}: #{e.message}", hint: hint)
      end
    end
  end
end
