# frozen_string_literal: true

module Syskit
  module Compat
    # The +Roby+ that robot configurations and bundles call, installed as
    # the top-level constant while an app is active. Roby (plans, tasks,
    # the execution engine) is not modelled: only what decides which models
    # and task libraries load is, the rest is accepted with a warning.
    module Roby
      # +Roby.app+: the loaded app as Roby's application object.
      class Application
        # Statements of Roby.app that only matter to a running system.
        NOT_MODELLED = %i[using load_plugins setup_robot_names_from_config_dir shell? public_logs?
                          log_dir register_generators].freeze

        # +app+: the active app (Roby's +Roby::Application.new+ takes none).
        def initialize(app = DSL.app!)
          @app = app
        end

        # The app's directory.
        def app_dir
          @app.root
        end

        # The app's namespace name (AppName).
        def module_name
          @app.name
        end

        # Directories of the app and the bundles it uses (see App#bundles).
        def search_path
          @app.bundle_roots.dup
        end

        def simulation?
          false
        end

        # Models have their current names (Syskit's naming conventions).
        def backward_compatible_naming?
          false
        end

        # The app's models are loaded anyway; accepted.
        def load_default_models; end

        # Another app whose models this one uses: read from the robot
        # configurations' text when the app is opened (see App::BundleSearch).
        def register_app(_path); end

        # Loads every task library on the search path, as Syskit does when
        # this is set in a robot configuration.
        def auto_load_all_task_libraries=(value)
          @app.load_all_task_libraries(location: Location.of_caller) if value
        end

        # +Roby.app.default_loader+: which typekits and task libraries exist.
        def default_loader
          self
        end

        # The type of that name (+/int+), resolved in the app's types.
        def resolve_type(name)
          @app.types.resolve(name, location: Location.of_caller)
        end

        def has_typekit?(name) # rubocop:disable Naming/PredicatePrefix -- Rock's name
          @app.typekit?(name.to_s)
        end

        def has_project?(name) # rubocop:disable Naming/PredicatePrefix -- Rock's name
          @app.orogen.available_library_names.include?(name.to_s)
        end

        NOT_MODELLED.each do |statement|
          define_method(statement) do |*_args, **_options, &_block|
            @app.not_modelled("Roby.app.#{statement}", Location.of_caller)
          end
        end
      end

      class << self
        def app
          Application.new(DSL.app!)
        end

        # Deprecation warnings of Rock's own code, shown at debug level.
        def warn_deprecated(message, *)
          Config::RobotDSL.log('debug', "deprecated: #{message}")
        end

        # Roby's scheduler runs tasks; accepted, with a warning.
        def scheduler=(_scheduler)
          DSL.app!.not_modelled('Roby.scheduler', Location.of_caller)
        end

        def to_s
          'Roby'
        end
        alias inspect to_s
      end
    end
  end
end
