# frozen_string_literal: true

require 'helper'

module Syskit
  # Syskit's connect_ports / disconnect_ports between two tasks held in a
  # plan: connections by port names, each checked before any is changed.
  class TestTaskConnections < Minitest::Test
    def setup
      double = Types::OpaqueType.new('/double')
      @source = TaskContext.new_submodel { output_port 'out', double }.new
      @sink = TaskContext.new_submodel do
        input_port 'in', double
        input_port 'other', double
      end.new
    end

    def test_connect_ports_links_the_named_ports
      @source.connect_ports(@sink, %w[out in] => { type: :buffer, size: 2 }, %w[out other] => nil)
      assert @source.out_port.connected_to?(@sink.in_port)
      assert @source.out_port.connected_to?(@sink.other_port)
      assert_equal [{ type: :buffer, size: 2 }, {}], @sink.connections.map(&:policy)
    end

    def test_connect_ports_checks_every_port_first
      error = assert_raises(ArgumentError) { @source.connect_ports(@sink, %w[out in] => {}, %w[out nothing] => {}) }
      assert_match(/has no input port 'nothing'/, error.message)
      assert_equal File.expand_path(__FILE__), error.location.path
      assert_empty @source.connections
      assert_raises(ArgumentError) { @source.connect_ports(@sink, %w[in in] => {}) }
    end

    def test_disconnect_ports_removes_the_named_connections_only
      @source.connect_ports(@sink, %w[out in] => {}, %w[out other] => {})
      @source.disconnect_ports(@sink, [%w[out other]])
      assert @source.out_port.connected_to?(@sink.in_port)
      refute @source.out_port.connected_to?(@sink.other_port)
      assert_equal 1, @sink.connections.size
    end

    def test_disconnecting_what_is_not_connected_is_an_argument_error
      @source.connect_ports(@sink, %w[out in] => {})
      error = assert_raises(ArgumentError) { @source.disconnect_ports(@sink, [%w[out in], %w[out other]]) }
      assert_match(/is not connected to/, error.message)
      assert @source.out_port.connected_to?(@sink.in_port), 'nothing removed'
      assert_raises(ArgumentError) { @source.disconnect_ports(@sink, [%w[nothing in]]) }
    end
  end
end
