# frozen_string_literal: true

module Syskit
  VERSION = '0.1.0'

  # This gem and Rock's own Syskit share their name, their executable and
  # `require 'syskit'`. Only this gem defines STANDALONE: code (and people)
  # that must tell them apart check `defined?(Syskit::STANDALONE)`.
  STANDALONE = true

  # What `syskit version` says besides the version number.
  ABOUT = "the standalone model layer of Syskit (devices, buses, network plans; no Roby, no Orocos), not Rock's Syskit"
end
