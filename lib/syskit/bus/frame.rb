# frozen_string_literal: true

module Syskit
  module Bus
    # One CAN frame, as SocketCAN describes it: +can_id+ holds the id and the
    # EFF (extended), RTR (remote request) and ERR (error frame) flags;
    # +len+ is the payload length (for an RTR frame, the requested length);
    # +data+ the payload as a binary string; +time+ the reception time in
    # microseconds since the epoch (an Integer, exact, as /base/Time counts;
    # nil when unknown); +fd_flags+ the CAN FD flags, nil for a classic frame.
    Frame = Struct.new(:can_id, :len, :data, :time, :fd_flags, keyword_init: true)

    # The flags, masks and kinds of a Frame.
    class Frame
      EFF_FLAG = 0x8000_0000
      RTR_FLAG = 0x4000_0000
      ERR_FLAG = 0x2000_0000
      SFF_MASK = 0x7FF
      EFF_MASK = 0x1FFF_FFFF
      CAN_MAX_LEN = 8
      CANFD_MAX_LEN = 64
      # The payload lengths a CAN FD frame can have (its DLC codes 0..15).
      CANFD_LENGTHS = [0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64].freeze

      # The key frames are dispatched and counted by: the id, with EFF_FLAG
      # for an extended frame, so that a standard and an extended frame with
      # the same number stay apart.
      def self.key(id, extended)
        extended ? id | EFF_FLAG : id
      end

      # The id written as candump writes it: 3 hex digits for a standard
      # frame, 8 for an extended one.
      def self.key_to_s(key)
        (key & EFF_FLAG).zero? ? format('%03X', key) : format('%08X', key & EFF_MASK)
      end

      def initialize(can_id:, len: nil, data: ''.b, time: nil, fd_flags: nil)
        data = data.b
        super(can_id: can_id, len: len || data.bytesize, data: data, time: time, fd_flags: fd_flags)
      end

      # The identifier without the flags.
      def id
        can_id & (extended? || error? ? EFF_MASK : SFF_MASK)
      end

      def extended?
        can_id & EFF_FLAG != 0
      end

      def rtr?
        can_id & RTR_FLAG != 0
      end

      def error?
        can_id & ERR_FLAG != 0
      end

      def fd?
        !fd_flags.nil?
      end

      # See Frame.key.
      def key
        Frame.key(id, extended?)
      end

      # The frame in candump's notation (the part after the interface name).
      def to_candump
        id_text = error? ? format('%08X', can_id & (EFF_MASK | ERR_FLAG)) : Frame.key_to_s(key)
        return "#{id_text}#R#{len if len.positive?}" if rtr?

        hex = data.unpack1('H*').upcase
        fd? ? "#{id_text}###{format('%X', fd_flags)}#{hex}" : "#{id_text}##{hex}"
      end
    end
  end
end
