# frozen_string_literal: true

# The gem's version and what it is, loaded alone by `syskit --version`.
module Syskit
  VERSION = '0.1.0'

  # This gem and Rock's own Syskit share their name, their executable and
  # `require 'syskit'`. Only this gem defines STANDALONE: code (and people)
  # that must tell them apart check `defined?(Syskit::STANDALONE)`.
  STANDALONE = true

  # What `syskit version` says besides the version number.
  ABOUT = "the standalone model layer of Syskit (devices, buses, network plans; no Roby, no Orocos), not Rock's Syskit"

  # What `syskit --version` prints: the version, what this gem is and where
  # it is installed. Needs nothing else of the gem: bin/syskit answers
  # --version before loading the command line.
  def self.version_text
    "syskit #{VERSION}\n#{ABOUT}, from #{File.expand_path('../..', __dir__)}\n"
  end
end
