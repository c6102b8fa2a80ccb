# frozen_string_literal: true

require 'syskit/errors'

module Syskit
  module Bus
    # A CAN log that cannot be read, or (with --strict) a malformed line.
    class LogError < Syskit::Error; end

    # A live CAN interface that cannot be opened or read.
    class InterfaceError < Syskit::Error; end
  end
end
