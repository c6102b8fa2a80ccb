# frozen_string_literal: true

module Syskit
  module Config
    # The +Robot+ of Rock's robot configuration files, installed as the
    # top-level constant while an app is active:
    #
    #   Robot.init { ... }        # evaluated first
    #   Robot.requires { ... }    # then: models to load, deployments
    #   Robot.config { ... }      # then
    #   Robot.controller { ... }  # recorded: runtime only, no effect on a plan
    #   Robot.actions { ... }     # recorded: runtime only, no effect on a plan
    #   Robot.info 'message'      # logs to stderr, from anywhere
    #
    # The blocks of a file are run once the whole file has been read, in
    # that order (see RobotConfigLoader).
    module RobotDSL
      # Blocks by phase, in the order they run, and whether they are run.
      PHASES = { init: :run, requires: :run, config: :run, controller: :recorded, actions: :recorded }.freeze

      # Log levels, lowest first. SYSKIT_LOG sets the lowest one printed.
      LEVELS = %w[debug info warn error fatal].freeze

      class << self
        PHASES.each_key do |phase|
          define_method(phase) do |&block|
            RobotDSL.record(phase, Location.of_caller, &block)
          end
        end

        LEVELS.each do |level|
          define_method(level) do |message = nil, &block|
            RobotDSL.log(level, block ? block.call : message)
          end
        end

        def to_s
          'Robot'
        end
        alias inspect to_s
      end

      # Records a phase block into the robot configuration being loaded.
      def self.record(phase, location, &block)
        config = Syskit.app&.loading_robot_config
        unless config
          raise DeclarationError.new(
            "Robot.#{phase} is only available in robot configuration files",
            location: location, hint: 'write it in config/robots/<robot>.rb'
          )
        end
        unless block
          raise DeclarationError.new("Robot.#{phase} needs a block",
                                     location: location, hint: "write Robot.#{phase} do ... end")
        end

        config.add_phase_block(phase, block, location)
      end

      # Prints +message+ on stderr when +level+ is at least SYSKIT_LOG's
      # (warn by default).
      def self.log(level, message)
        threshold = LEVELS.index(ENV.fetch('SYSKIT_LOG', 'warn').downcase) || LEVELS.index('warn')
        Kernel.warn("Robot #{level.upcase}: #{message}") if LEVELS.index(level) >= threshold
        nil
      end
    end
  end
end
