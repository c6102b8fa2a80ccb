# frozen_string_literal: true

require 'syskit/models/bound_data_service'

module Syskit
  module Models
    # A service a task model has because a dynamic service was required
    # of it (+require_dynamic_service('test', as: 'x', option1: 42)+), as
    # Syskit's BoundDynamicDataService: +dynamic_service+ and
    # +dynamic_service_options+ say where it comes from.
    class BoundDynamicDataService < BoundDataService
      # Two instances are one service when they come from the same
      # dynamic service (on whichever submodel it was required) with the
      # same options.
      def same_service?(other)
        other.is_a?(BoundDynamicDataService) &&
          other.dynamic_service.demoted.equal?(dynamic_service.demoted) &&
          other.dynamic_service_options == dynamic_service_options
      end
    end
  end
end
