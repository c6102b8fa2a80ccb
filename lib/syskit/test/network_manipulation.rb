# frozen_string_literal: true

module Syskit
  module Test
    # Network generation in Syskit's tests: requirements to tasks, with
    # stubbed deployments (see Stubs#syskit_stub_and_deploy).
    module NetworkManipulation
    end
  end
end
