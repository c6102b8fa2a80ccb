# frozen_string_literal: true

require 'helper'

module Syskit
  # Syskit.resolve_connections: which output goes to which input when
  # components are connected without naming ports.
  class TestConnectionResolution < Minitest::Test
    FakePort = Struct.new(:name, :type, :multiplexes) do
      def multiplexes?
        !!multiplexes
      end
    end

    def ports(*specs)
      specs.map { |name, type, mux| FakePort.new(name, type, mux) }
    end

    def test_an_output_goes_to_the_only_input_of_its_type
      outs = ports(%w[pose /rbs], %w[cmd /joints])
      ins = ports(%w[joints_in /joints], %w[pose_in /rbs])
      assert_equal [[outs[0], ins[1]], [outs[1], ins[0]]], Syskit.resolve_connections(outs, ins)
    end

    def test_the_name_picks_among_inputs_of_the_same_type
      outs = ports(%w[left /img], %w[right /img])
      ins = ports(%w[right /img], %w[left /img], %w[center /img])
      assert_equal [[outs[0], ins[1]], [outs[1], ins[0]]], Syskit.resolve_connections(outs, ins)
    end

    def test_several_inputs_of_the_type_and_none_of_the_name_is_ambiguous
      error = assert_raises(AmbiguousAutoConnection) do
        Syskit.resolve_connections(ports(%w[out /img]), ports(%w[a /img], %w[b /img]))
      end
      assert_match(/out could connect to several inputs: a, b/, error.message)
    end

    def test_several_outputs_into_one_input_need_it_to_multiplex
      outs = ports(%w[a /img], %w[b /img])
      assert_raises(AmbiguousAutoConnection) { Syskit.resolve_connections(outs, ports(%w[in /img])) }
      mux = ports(['in', '/img', true])
      assert_equal [[outs[0], mux[0]], [outs[1], mux[0]]], Syskit.resolve_connections(outs, mux)
    end

    def test_outputs_without_an_input_of_their_type_connect_nowhere
      assert_empty Syskit.resolve_connections(ports(%w[out /img]), ports(%w[in /rbs]))
    end
  end
end
