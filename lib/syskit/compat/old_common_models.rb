# frozen_string_literal: true

module Syskit
  module Compat
    # common_models was the 'rock' bundle before 2017: its files were
    # required as 'rock/models/...' and its models were Rock::Services::...,
    # Rock::Devices::... Bundles of that time still write those names.
    module OldCommonModels
      OLD_REQUIRE = %r{\Arock/models/}

      module_function

      # Whether +name+ is a require of the old bundle.
      def require_path?(name)
        OLD_REQUIRE.match?(name.to_s)
      end

      # The file's current name: common_models/models/...
      def current_require(name)
        name.to_s.sub(OLD_REQUIRE, 'common_models/models/')
      end

      # A require of the old bundle that is not on the load path (no 'rock'
      # bundle): the current file is loaded instead, with a warning saying
      # so. When common_models has no such file either, the warning says
      # that, and the file goes on loading as after any require of Rock's
      # that is not here.
      def require_instead(name, location)
        current = current_require(name)
        app = DSL.app!
        file = app.required_file(current)
        found = file || $LOAD_PATH.resolve_feature_path(current)
        app.problems << (found ? loaded_instead(name, current, location) : not_found(name, current, location))
        return app.load_file(file) if file

        found ? Kernel.require(current) : false
      end

      def loaded_instead(name, current, location)
        Warning.new("#{name} is common_models' file under its name before 2017 (the 'rock' bundle): " \
                    "#{current} is loaded instead",
                    location: location, hint: "write require '#{current}' (and CommonModels:: for Rock::)")
      end

      def not_found(name, current, location)
        Warning.new("#{name} is common_models' file under its name before 2017 (the 'rock' bundle), and " \
                    "common_models has no #{current.delete_prefix('common_models/')} either: not loaded",
                    location: location,
                    hint: 'add the bundle that has it to config/syskit.yml (bundles: [...]), or require the file ' \
                          'under its current name')
      end

      # The hint for an unknown constant +Rock+ (Rock::Services::Pose).
      def constant_hint
        'Rock:: is common_models under its name before 2017: write CommonModels:: instead ' \
          "(Rock::Services::Pose is CommonModels::Services::Pose), or add the old 'rock' bundle to config/syskit.yml"
      end
    end
  end
end
