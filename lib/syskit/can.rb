# frozen_string_literal: true

module Syskit
  # CAN identifiers and filters, shared by the bundled CAN bus model, the
  # filter-overlap check and the bus traffic tools.
  module CAN
    STANDARD_ID_MAX = 0x7FF
    EXTENDED_ID_MAX = 0x1FFF_FFFF

    # A device's receive filter: it gets the frames with (frame_id & mask) == id.
    #
    # Standard (11-bit) and extended (29-bit) frames are kept apart: a filter
    # whose id or mask does not fit in 11 bits can only mean extended frames,
    # so it is an extended filter and matches extended frames only; any other
    # filter matches standard frames only. {#match?} compares ids alone; the
    # bus traffic tools (Syskit::Bus::Dispatcher) apply the frame kind too.
    Filter = Struct.new(:id, :mask) do
      def match?(frame_id)
        (frame_id & mask) == id
      end

      # Whether this filter is for extended (29-bit) frames.
      def extended?
        id > STANDARD_ID_MAX || mask > STANDARD_ID_MAX
      end

      # Whether some frame id passes both filters.
      def overlap?(other)
        ((id ^ other.id) & mask & other.mask).zero?
      end

      # Whether some frame id passes the filter: not when the id has bits
      # outside the mask.
      def matchable?
        (id & mask) == id
      end

      def to_s
        format('id 0x%<id>X mask 0x%<mask>X', id: id, mask: mask)
      end
    end

    module_function

    # The value of a device's +can_id(id, mask)+: the pair as given, once
    # both are integers that fit in 29 bits (else ArgumentError). A filter
    # that can never match is stored too (the seed's own test writes
    # +can_id(10, 20)+): `syskit check` warns about it (Checks::CanFilters).
    def filter_value(id, mask)
      check_filter_part('id', id)
      check_filter_part('mask', mask)
      [id, mask]
    end

    def check_filter_part(what, value)
      raise ArgumentError, "the #{what} must be an integer, got #{value.inspect}" unless value.is_a?(Integer)
      return if value.between?(0, EXTENDED_ID_MAX)

      raise ArgumentError, format('the %<what>s 0x%<v>X does not fit in 29 bits (CAN ids are 11-bit standard ' \
                                  'or 29-bit extended, at most 0x%<max>X)',
                                  what: what, v: value, max: EXTENDED_ID_MAX)
    end
  end
end
