# frozen_string_literal: true

module Syskit
  module Orogen
    # Statements of a +deployment "name" do ... end+ block.
    class DeploymentDSL
      include StatementsDSL

      # What +task(...)+ returns: activity settings, accepted.
      class DeployedTaskDSL
        %i[periodic realtime non_realtime priority triggered fd_driven sequential slave_of
           stacksize start port_driven].each do |setting|
          define_method(setting) { |*_args, **_options| self }
        end
      end

      def initialize(loader, deployment)
        @loader = loader
        @deployment = deployment
      end

      def dsl_context
        "deployment '#{@deployment.name}'"
      end

      def task(task_name, model_name)
        location = Location.of_caller
        model = @loader.find_task_model(model_name.to_s, location)
        @deployment.add_task(task_name.to_s, model, location: location)
        DeployedTaskDSL.new
      end

      def corba_enabled?
        true
      end

      # Runtime-only statements: accepted.
      %i[add_default_logger browse do_not_install add_peers connect toplevel].each do |statement|
        define_method(statement) { |*_args, **_options| nil }
      end
    end
  end
end
