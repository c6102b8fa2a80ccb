# frozen_string_literal: true

module Syskit
  module Network
    # Connection policies. A connection into a bus driver's input, or into a
    # port that needs_reliable_connection, is buffered; its size is
    #
    #   sample_size * (burst + ceil(latency / period))
    #
    # where period and burst are the device's (+.period(s)+, +.burst(n)+,
    # burst 1 when not given) and latency is the reading task model's
    # worstcase_processing_time (DEFAULT_LATENCY when not declared): the
    # samples the device can send while the reader is busy. Without a period
    # the samples are burst + DEFAULT_BUFFER_SIZE - 1 (20 with no burst).
    # As in Syskit's dataflow dynamics, +.sample_size(n)+ (the bus messages
    # one sample of the device takes, 1 when not given) counts on the
    # connections from the bus to the device; the device's own writes to
    # the bus are counted in samples. A port's needs_buffered_connection(n)
    # is a minimum. Other connections get a data policy (the last sample
    # only). A bus model declared override_policy: false does not buffer the
    # inputs of its driver that do not ask for it.
    module Policy
      DEFAULT_BUFFER_SIZE = 20
      DEFAULT_LATENCY = 0.1

      module_function

      DATA = { 'type' => 'data' }.freeze

      # The policy of a connection into +sink_port+ of +sink_task+ on the
      # link of the attached +device+; +into_bus+: the device writes to its
      # bus (else the bus writes to the device).
      def for(sink_port, sink_task, device, into_bus:)
        forced = into_bus && device.bus.model.override_policy?
        return DATA unless forced || sink_port.reliable? || sink_port.buffer_size

        size = buffer_size(device, sink_task.model.worstcase_processing_time)
        size *= device.sample_size || 1 unless into_bus
        size = [size, sink_port.buffer_size].max if sink_port.buffer_size
        buffer(size)
      end

      # The policy of a composition's connection into +sink_port+ that
      # declares none: buffered when the port needs it, else data.
      def for_port(sink_port)
        return DATA unless sink_port.reliable? || sink_port.buffer_size

        buffer([DEFAULT_BUFFER_SIZE, sink_port.buffer_size || 0].max)
      end

      # A declared policy (+connect_to port, type: :buffer, size: 10+), at
      # least what the sink port needs.
      def declared(policy, sink_port)
        return policy unless policy['type'] == 'buffer' && sink_port.buffer_size
        return policy if (policy['size'] || 0) >= sink_port.buffer_size

        policy.merge('size' => sink_port.buffer_size).freeze
      end

      # A policy as a model keeps it (+{ type: :buffer, size: 10 }+), as
      # the plan writes it (+{ 'type' => 'buffer', 'size' => 10 }+).
      def of(policy)
        policy.to_h { |k, v| [k.to_s, v.is_a?(Symbol) ? v.to_s : v] }.freeze
      end

      # Policies are values: one frozen hash per size.
      def buffer(size)
        (@buffers ||= {})[size] ||= { 'type' => 'buffer', 'size' => size }.freeze
      end

      # The samples +device+ may send while its reader is busy for +latency+.
      def buffer_size(device, latency)
        burst = device.burst || 1
        period = device.period
        return burst + DEFAULT_BUFFER_SIZE - 1 unless period

        # burst(0) with no latency would otherwise make an empty buffer.
        [burst + ((latency || DEFAULT_LATENCY) / period.to_f).ceil, 1].max
      end
    end
  end
end
