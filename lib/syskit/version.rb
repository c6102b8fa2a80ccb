# frozen_string_literal: true

module Syskit
  VERSION = '0.1.0'
end
