# frozen_string_literal: true

require 'psych'
require 'syskit/app/files'
require 'syskit/app/environment'
require 'syskit/app/registered_apps'
require 'syskit/app/bundles'
require 'syskit/app/settings_yaml'
require 'syskit/app/settings'
require 'syskit/app/everything'
require 'syskit/app/conf_files'
require 'syskit/app/init_file'
require 'syskit/app/robot_files'
require 'syskit/types/typekit_search'
require 'syskit/config/robot_config_loader'

module Syskit
  # A Syskit app (a "bundle"): a directory with models/, config/ and test/.
  #
  # The app finds and loads its files, owns everything they define (types,
  # task libraries, models, profiles, robot configurations) and removes it
  # all again on {#unload}, so that one process can load app after app.
  class App
    include Files
    include Everything
    include ConfFiles

    CONFIG_FILE = 'config/syskit.yml'
    BUNDLED_MODELS = File.join(BundleSearch::BUNDLED.root, 'models')

    attr_reader :root, :name, :acronyms, :types, :orogen, :profiles, :problems, :bundles

    # Whether +dir+ is an app (see ROOT_DIRS and ROOT_FILES). The gem itself
    # never is: its models/ directory is the bundled common_models (see
    # BundleSearch::BUNDLED), not an app's.
    def self.root?(dir)
      return false if File.identical?(dir, BundleSearch::BUNDLED.root)

      ROOT_DIRS.any? { |d| File.directory?(File.join(dir, d)) } ||
        ROOT_FILES.any? { |f| File.file?(File.join(dir, f)) }
    end

    # What makes a directory an app: this gem's layout, and what Rock
    # bundles have (older ones only config/bundle.yml or config/init.rb
    # beside their configuration files).
    ROOT_DIRS = %w[models config/robots config/orogen].freeze
    ROOT_FILES = [CONFIG_FILE, 'config/app.yml', 'config/bundle.yml', 'config/init.rb'].freeze

    # +dir+ given as an app (--app): its root, or an error saying what it
    # is instead (nothing, a file, a directory inside an app).
    def self.check_root(dir)
      path = File.expand_path(dir)
      return path if File.directory?(path) && root?(path)

      inside = File.directory?(path) && find_root(path)
      what = if !File.exist?(path) then 'there is no such directory'
             elsif !File.directory?(path) then 'it is a file, not a directory'
             elsif File.identical?(path, BundleSearch::BUNDLED.root)
               "it is the syskit gem itself (its models/ are the gem's own common_models)"
             elsif inside then "it is inside the app at #{inside}"
             else 'it is not a Syskit app'
             end
      raise FileLoadError.new("'#{dir}' is not an app: #{what}",
                              hint: inside ? "give --app #{inside}" : APP_HINT)
    end

    APP_HINT = 'an app has a models/ directory or a config/syskit.yml (a Rock bundle a config/app.yml, ' \
               'config/robots/ or config/orogen/); create one with: syskit gen app NAME'

    # The app containing +dir+: the closest parent that is one (see root?).
    def self.find_root(dir = Dir.pwd)
      dir = File.expand_path(dir)
      loop do
        return dir if root?(dir)

        parent = File.dirname(dir)
        return nil if parent == dir

        dir = parent
      end
    end

    def initialize(root, name: nil, orogen_path: ENV.fetch('SYSKIT_OROGEN_PATH', ''))
      @root = File.expand_path(root)
      config = Settings.new(@root, name: name)
      @acronyms = config.acronyms
      @name = config.name
      @orogen_path = orogen_path.split(File::PATH_SEPARATOR).reject(&:empty?).map { |d| File.expand_path(d) }
      @bundles, @problems = BundleSearch.new.resolve(@root, @name, config)
      @problems.unshift(*config.problems)
      @types = Types::Registry.new
      @typekits = Types::TypekitSearch.new(@types, typekit_search_dirs)
      @robot_config_loader = Config::RobotConfigLoader.new(self)
      @environment = Environment.new(self)
      @profiles = {}
    end

    # The directories of the app and of the bundles it uses, in search order.
    def bundle_roots
      bundles.map(&:root)
    end

    def to_s
      "app #{name} (#{root})"
    end

    def inspect
      "#<#{self.class.name} #{name} #{root}>"
    end

    # Directories searched for NAME.orogen, in order: the bundles' (the
    # app's first), SYSKIT_OROGEN_PATH, then the gem's own.
    def orogen_search_dirs
      search_dirs('orogen')
    end

    # Directories searched for typekits (NAME.rb), in the same order.
    def typekit_search_dirs
      search_dirs('typekits')
    end

    # Loads the whole app: models, task libraries, profiles and the
    # configuration of +robots+ ('default' unless given; :all for every one).
    # Problems are collected in {#problems}; {#load!} raises them instead.
    #
    # Task libraries are loaded by using_task_library statements, as in
    # Syskit: the drivers a profile can use are the ones its files ask for.
    # With +everything: true+ (syskit check), every task library and typekit
    # of the app is loaded afterwards too, so that their problems are found.
    #
    # With +models: false+, the files under models/ are loaded only when
    # something requires them (a robot configuration's Robot.requires
    # block, a test file), as Roby loads an app whose config/init.rb sets
    # auto_load_models to false; by default, as the app's config/init.rb
    # says (see InitFile).
    def load(robots: ['default'], everything: false, models: InitFile.auto_load_models?(root))
      activate
      load_bundled_models
      load_model_files if models
      load_robot_configs(robots)
      collect_problems { resolve_devices }
      load_everything if everything
      self
    end

    def load!(**options)
      load(**options)
      ErrorList.raise_if_any(errors)
      self
    end

    # The problems found so far that are errors (not warnings).
    def errors
      problems.grep_v(Warning)
    end

    # Records a construct of a real Rock file that this gem does not model,
    # once per place.
    def not_modelled(what, location)
      return if problems.any? { |p| p.is_a?(NotModelled) && p.location == location && p.message.start_with?(what) }

      problems << NotModelled.new(what, location: location)
    end

    # Records a warning, once per place and message (a plan applies the
    # same configuration section to many tasks).
    def warning(message, location:, hint: nil)
      warning = Warning.new(message, location: location, hint: hint)
      problems << warning unless problems.any? { |p| p.identity == warning.identity }
    end

    # Makes this app the one DSL statements (device_type, using_task_library,
    # Syskit.conf, OroGen, Types...) act on.
    def activate
      return self if @environment.active?

      @environment.activate
      @orogen = Orogen::Loader.new(self)
      @environment.install_constants
      self
    end

    # The top-level modules the app's files (and its bundles') defined,
    # by name, while it is active.
    def defined_modules
      @environment.defined_modules
    end

    # Removes everything the app defined: constants, loaded files, load path.
    def unload
      @environment.deactivate
    end

    # Loads task library +name+ (its .orogen file and extension files) once.
    def using_task_library(name, location: Location.of_caller)
      return orogen.library(name) if orogen.loaded?(name)

      library = orogen.load_library(name, location)
      extension_files(name, library.path).each { |path| load_file(path) }
      library
    end

    # Extension files of a task library: models/orogen/NAME.rb of every
    # bundle, and the file next to its .orogen file. The gem's extension of
    # its own canbus spec gives way to a bundle's (Rock's common_models has
    # one).
    def extension_files(name, spec_path)
      beside = File.join(File.dirname(spec_path), "#{name}.rb")
      own = bundles.reject { |b| b.equal?(BundleSearch::BUNDLED) }.filter_map { |b| b.file("models/orogen/#{name}.rb") }
      return own if beside.start_with?("#{BUNDLED_MODELS}/") && own.any?

      (own + [beside]).uniq.select { |p| File.file?(p) }
    end

    # Typekits imported without a description (their types are opaque),
    # with where each was first imported.
    def opaque_typekits
      @typekits.opaque
    end

    # Whether typekit +name+ is known (built in or described).
    def typekit?(name)
      Types::Registry::BUILTIN_TYPEKITS.include?(name) || !@typekits.find(name).nil?
    end

    # Syskit's +app.default_loader+: what resolves type names
    # (+resolve_type '/int'+) and knows the typekits and task libraries.
    def default_loader
      Compat::Roby::Application.new(self)
    end

    # Loads every task library on the search path (Rock's
    # Roby.app.auto_load_all_task_libraries); problems are collected.
    def load_all_task_libraries(location:)
      orogen.available_library_names.each do |lib|
        collect_problems { using_task_library(lib, location: location) }
      end
    end

    # import_types_from (see Types::TypekitSearch#import).
    def import_types(name, location: Location.of_caller)
      @typekits.import(name, location: location)
    end

    # Whether +path+ is a file of the app or of one of its bundles.
    def environment_file?(path)
      @environment.owned_file?(path)
    end

    # Records a profile defined by a file of this app.
    def register_profile(profile)
      @profiles[profile.name] = profile
    end

    # The deployments of robot +name+, loaded from config/robots/NAME.rb.
    def robot_config(name = 'default')
      @robot_config_loader[name]
    end

    # The robot configurations loaded so far, by name.
    def robot_configs
      @robot_config_loader.loaded
    end

    # The robot configuration file being evaluated, for Syskit.conf.
    def loading_robot_config
      @robot_config_loader.loading
    end

    def robot_config_names
      @robot_config_loader.names
    end

    # Resolves the model and driver of every device of every profile.
    def resolve_devices
      index = Robot::DriverIndex.new(orogen, self)
      ErrorList.raise_if_any(profiles.values.flat_map { |p| p.robot.resolve(index) })
    end

    private

    def load_model_files
      each_model_file.each { |path| collect_problems { load_file(path) } }
    end

    # A missing robot configuration is reported when a plan needs it.
    def load_robot_configs(robots)
      names = robots == :all ? robot_config_names : Array(robots)
      names.select { |r| robot_config_names.include?(r) }.each { |robot| collect_problems { robot_config(robot) } }
    end

    # A problem met again (a task library that failed to load, asked for
    # by a profile and by a robot configuration) is kept once.
    def collect_problems
      yield
    rescue Syskit::ErrorList => e
      e.errors.each { |error| add_problem(error) }
    rescue Syskit::Error => e
      add_problem(e)
    end

    def add_problem(problem)
      return if problem.is_a?(FollowOnError)

      @problem_keys ||= @problems.to_h { |p| [p.identity, true] }
      @problems << problem unless @problem_keys.key?(problem.identity)
      @problem_keys[problem.identity] = true
    end

    # The CAN bus model of the first common_models bundle: the seed uses
    # it without a require.
    def load_bundled_models
      can = bundles.select { |b| b.name == 'common_models' }
                   .filter_map { |b| b.file('models/devices/bus/can.rb') }.first
      collect_problems { load_file(can) }
    end

    def search_dirs(kind)
      own = bundles.reject { |b| b.equal?(BundleSearch::BUNDLED) }.map { |b| File.join(b.root, 'models', kind) }
      [*own, *@orogen_path, File.join(BUNDLED_MODELS, kind)]
    end
  end
end
