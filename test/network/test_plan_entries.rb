# frozen_string_literal: true

require 'helper'

module Syskit
  module Network
    # Plan entries built by field name, as tests and tools write them.
    class TestPlanEntries < Minitest::Test
      def test_named_fields_are_set_and_the_others_are_nil
        device = Plan::Device.with(name: 'gps', bus: 'can0', attributes: { 'can_id' => [1, 2] })
        assert_equal 'gps', device.name
        assert_equal 'can0', device.bus
        assert_equal({ 'can_id' => [1, 2] }, device.attributes)
        assert_nil device.task
        assert_equal Plan::Device.new('gps', nil, nil, 'can0', nil, nil, { 'can_id' => [1, 2] }), device
      end

      def test_an_unknown_field_is_an_error_that_lists_the_fields
        error = assert_raises(ArgumentError) { Plan::Port.with(name: 'out', kind: 'output') }
        assert_equal 'Syskit::Network::Plan::Port has no kind; its fields are name, direction, type, dynamic, ' \
                     'declared_type', error.message
      end
    end
  end
end
