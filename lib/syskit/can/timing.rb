# frozen_string_literal: true

require 'syskit/can/timing/frame'
require 'syskit/can/timing/result'
require 'syskit/can/timing/analysis'
require 'syskit/can/timing/format'

module Syskit
  module CAN
    # Worst-case timing of CAN buses: the frames devices declare
    # (Timing::Frame), the response-time analysis (Timing::Analysis) and its
    # results. Plain values and functions: the DSL statements that declare
    # frames live in Syskit::Robot::CanTraffic.
    module Timing
    end
  end
end
