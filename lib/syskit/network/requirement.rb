# frozen_string_literal: true

module Syskit
  module Network
    # A device to put in a network: a profile's +gps_dev+ action, optionally
    # with other configuration sections or deployment hints than the
    # device's own (+Base.gps_dev.with_conf('default', 'rtk')+ returns a copy).
    class Requirement
      attr_reader :device, :profile, :arguments

      NO_ARGUMENTS = {}.freeze

      # +arguments+: task arguments for the driver (tests' with_arguments).
      def initialize(device, profile = nil, conf: nil, deployment_hints: nil, arguments: NO_ARGUMENTS)
        @device = device
        @profile = profile
        @conf = conf
        @deployment_hints = deployment_hints
        @arguments = arguments
      end

      def conf
        @conf || device.conf
      end

      def deployment_hints
        @deployment_hints || device.deployment_hints
      end

      def with_conf(*names)
        Requirement.new(device, profile, conf: names.flatten.map(&:to_s).freeze, deployment_hints: @deployment_hints)
      end

      def prefer_deployed_tasks(*hints)
        Requirement.new(device, profile, conf: @conf, deployment_hints: deployment_hints + hints.flatten)
      end

      def name
        "#{device.name}_dev"
      end

      def to_s
        profile ? "#{profile}.#{name}" : name
      end
      alias inspect to_s
    end
  end
end
