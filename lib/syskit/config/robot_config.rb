# frozen_string_literal: true

module Syskit
  module Config
    # What is deployed on one robot: the file config/robots/<name>.rb, where
    # +Syskit.conf+ is this object.
    #
    #   Syskit.conf.use_deployment 'test_canbus'              # a deployment of an .orogen file
    #   Syskit.conf.use_deployment OroGen.gps_ublox.Task => 'gps'  # one task, named 'gps'
    #
    # Its deployment statements are those of every deployment group (see
    # Models::DeploymentGroup); the file's phases and the runtime's
    # statements are its own.
    class RobotConfig < Models::DeploymentGroup
      include ProcessServers

      # Statements of Syskit.conf about a running system (how the local
      # process server runs; simulators, logging, ruby tasks): accepted,
      # with a "not modelled" warning each (see Compat). Process servers
      # themselves are data (see ProcessServers).
      NOT_MODELLED = %i[use_gazebo_world redirect_local_process_server disables_local_process_server
                        transformer_enabled= export_types= auto_restart_deployments_with_quarantines=
                        exception_transition_timeout= logs only_load_models=].freeze

      # A Robot.init/requires/config/controller/actions block of the file.
      PhaseBlock = Struct.new(:phase, :block, :location)

      attr_reader :name

      def initialize(app, name)
        super(app)
        @name = name
        @phase_blocks = []
      end

      # Simulation is not modelled: plans are of the real robot.
      def sim?
        false
      end

      NOT_MODELLED.each do |statement|
        define_method(statement) do |*_args, **_options, &_block|
          app.not_modelled("Syskit.conf.#{statement}", Location.of_caller)
          Compat::Ignored.instance
        end
      end

      # Records a Robot.init/requires/... block (see Config::RobotDSL).
      def add_phase_block(phase, block, location)
        @phase_blocks << PhaseBlock.new(phase, block, location)
      end

      # The files this robot's configuration required as it loaded, and
      # those of the profiles its Robot.actions blocks use (see
      # App::RobotFiles): what Roby loads for this robot.
      def loaded_files
        @loaded_files ||= Set.new
      end

      def phase_blocks(phase)
        @phase_blocks.select { |entry| entry.phase == phase }
      end

      def to_s
        "robot '#{name}'"
      end

      def inspect
        "#<#{self.class.name} #{name}: #{@deployed_tasks.keys.join(', ')}>"
      end
    end
  end
end
