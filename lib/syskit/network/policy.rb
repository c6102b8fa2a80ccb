# frozen_string_literal: true

module Syskit
  module Network
    # Connection policies. A connection into a bus driver's input, or into a
    # port that needs_reliable_connection, is buffered; its size is
    #
    #   burst + ceil(latency / period)
    #
    # where period and burst are the writing device's (+.period(s)+,
    # +.burst(n)+, burst 1 when not given) and latency is the reading task
    # model's worstcase_processing_time (DEFAULT_LATENCY when not declared):
    # the messages the device can send while the reader is busy. Without a
    # period the size is burst + DEFAULT_BUFFER_SIZE - 1 (20 with no burst).
    # A port's needs_buffered_connection(n) is a minimum. Other connections
    # get a data policy (the last sample only).
    module Policy
      DEFAULT_BUFFER_SIZE = 20
      DEFAULT_LATENCY = 0.1

      module_function

      DATA = { 'type' => 'data' }.freeze

      def for(sink_port, sink_task, writer_device, into_bus:)
        return DATA unless into_bus || sink_port.reliable? || sink_port.buffer_size

        size = buffer_size(writer_device, sink_task.model.worstcase_processing_time)
        size = [size, sink_port.buffer_size].max if sink_port.buffer_size
        buffer(size)
      end

      # Policies are values: one frozen hash per size.
      def buffer(size)
        (@buffers ||= {})[size] ||= { 'type' => 'buffer', 'size' => size }.freeze
      end

      def buffer_size(device, latency)
        burst = device.burst || 1
        period = device.period
        return burst + DEFAULT_BUFFER_SIZE - 1 unless period

        burst + ((latency || DEFAULT_LATENCY) / period.to_f).ceil
      end
    end
  end
end
