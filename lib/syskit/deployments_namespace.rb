# frozen_string_literal: true

# Where deployment models registered by name live (+Deployments::MotorController+,
# see Syskit::Models::Deployment#define_from_orogen). Syskit defines it
# whether or not any is registered, and its tests mock it.
module Deployments; end
