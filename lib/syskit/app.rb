# frozen_string_literal: true

require 'psych'
require 'syskit/app/files'

module Syskit
  # A Syskit app (a "bundle"): a directory with models/, config/ and test/.
  #
  # The app finds and loads its files, owns everything they define (types,
  # task libraries, models, profiles, robot configurations) and removes it
  # all again on {#unload}, so that one process can load app after app.
  class App
    include Files

    CONFIG_FILE = 'config/syskit.yml'
    BUNDLED_MODELS = File.expand_path('../../models', __dir__)

    attr_reader :root, :name, :acronyms, :types, :orogen, :profiles, :robot_configs, :problems

    # The app containing +dir+: the closest parent with a models/ directory
    # or a config/syskit.yml file.
    def self.find_root(dir = Dir.pwd)
      dir = File.expand_path(dir)
      loop do
        return dir if File.directory?(File.join(dir, 'models')) || File.file?(File.join(dir, CONFIG_FILE))

        parent = File.dirname(dir)
        return nil if parent == dir

        dir = parent
      end
    end

    def initialize(root, name: nil, orogen_path: ENV.fetch('SYSKIT_OROGEN_PATH', ''))
      @root = File.expand_path(root)
      config = read_config
      @acronyms = Array(config['acronyms']).map(&:to_s)
      @name = name || config['name'] || Naming.camelize(File.basename(@root), @acronyms)
      @orogen_path = orogen_path.split(File::PATH_SEPARATOR).reject(&:empty?).map { |d| File.expand_path(d) }
      @types = Types::Registry.new
      @profiles = {}
      @robot_configs = {}
      @problems = []
      @typekits = {}
    end

    def to_s
      "app #{name} (#{root})"
    end

    def inspect
      "#<#{self.class.name} #{name} #{root}>"
    end

    # Directories searched for NAME.orogen, in order.
    def orogen_search_dirs
      [File.join(root, 'models', 'orogen'), *@orogen_path, File.join(BUNDLED_MODELS, 'orogen')]
    end

    # Directories searched for typekits (NAME.rb), in order.
    def typekit_search_dirs
      [File.join(root, 'models', 'typekits'), *@orogen_path, File.join(BUNDLED_MODELS, 'typekits')]
    end

    # Loads the whole app: models, task libraries, profiles and the
    # configuration of +robots+ ('default' unless given; :all for every one).
    # Problems are collected in {#problems}; {#load!} raises them instead.
    #
    # Task libraries are loaded by using_task_library statements, as in
    # Syskit: the drivers a profile can use are the ones its files ask for.
    # With +everything: true+ (syskit check), every task library and typekit
    # of the app is loaded afterwards too, so that their problems are found.
    def load(robots: ['default'], everything: false)
      activate
      load_bundled_models
      each_model_file.each { |path| collect_problems { load_file(path) } }
      # A missing robot configuration is reported when a plan needs it.
      robot_names(robots).select { |r| robot_config_names.include?(r) }
                         .each { |robot| collect_problems { robot_config(robot) } }
      collect_problems { resolve_devices }
      load_everything if everything
      self
    end

    def load!(**options)
      load(**options)
      ErrorList.raise_if_any(problems)
      self
    end

    # Makes this app the one DSL statements (device_type, using_task_library,
    # Syskit.conf, OroGen, Types...) act on.
    def activate
      return self if Syskit.app.equal?(self)
      raise Error, "#{Syskit.app} is still loaded, unload it first" if Syskit.app

      @constants_before = Object.constants
      # 'models/devices/x' and 'devices/x' resolve from the app; 'app_name/models/x'
      # (the seed's NMEA2000 example) through its parent, searched last.
      @load_path = [root, File.join(root, 'models'), File.dirname(root)]
      $LOAD_PATH.unshift(*@load_path.first(2))
      $LOAD_PATH.push(@load_path.last)
      Syskit.app = self
      @orogen = Orogen::Loader.new(self)
      replace_constant(:OroGen, @orogen.namespace)
      replace_constant(:Types, types.namespace)
      self
    end

    # Removes everything the app defined: constants, loaded files, load path.
    def unload
      return unless Syskit.app.equal?(self)

      (Object.constants - @constants_before).each do |const|
        Object.send(:remove_const, const) if owned_constant?(const)
      end
      %i[OroGen Types].each { |c| Object.send(:remove_const, c) if Object.const_defined?(c, false) }
      $LOADED_FEATURES.reject! { |f| owned_file?(f) }
      @load_path.each { |dir| $LOAD_PATH.delete(dir) }
      Syskit.app = nil
    end

    # Loads task library +name+ (its .orogen file and extension files) once.
    def using_task_library(name, location: Location.of_caller)
      return orogen.library(name) if orogen.loaded?(name)

      library = orogen.load_library(name, location)
      extension_files(name, library.path).each { |path| load_file(path) }
      library
    end

    # Extension files of a task library: next to its .orogen file, and the
    # app's models/orogen/NAME.rb.
    def extension_files(name, spec_path)
      [File.join(File.dirname(spec_path), "#{name}.rb"), File.join(root, 'models', 'orogen', "#{name}.rb")]
        .uniq.select { |p| File.file?(p) }
    end

    # import_types_from: returns :typekit when the typekit's types are known,
    # :header for C/C++ headers and, in .orogen files, :opaque for typekits the
    # gem has no description of (their types are then accepted as opaque).
    def import_types(name, location: Location.of_caller, from_spec: false)
      return :header if name.match?(/\.(h|hh|hpp|hxx)\z/i)
      return @typekits[name] if @typekits.key?(name)
      return @typekits[name] = :typekit if Types::Registry::BUILTIN_TYPEKITS.include?(name)

      path = typekit_search_dirs.map { |d| File.join(d, "#{name}.rb") }.find { |p| File.file?(p) }
      if path
        @typekits[name] = :typekit
        importer = ->(typekit, at) { import_types(typekit, location: at) }
        Types::TypekitLoader.new(types, name, importer).load(path)
      elsif from_spec
        types.opaque_typekit(name)
        @typekits[name] = :opaque
      else
        raise FileLoadError.new("no typekit '#{name}'",
                                location: location, hint: "declare its types in models/typekits/#{name}.rb")
      end
    end

    # The configuration file of +task_model+ (config/orogen/<lib>::<Task>.yml),
    # nil when there is none.
    def conf_file(task_model)
      @conf_files ||= {}
      return @conf_files[task_model.name] if @conf_files.key?(task_model.name)

      path = File.join(root, 'config', 'orogen', "#{task_model.name}.yml")
      @conf_files[task_model.name] = File.file?(path) ? Config::ConfFile.new(path) : nil
    end

    # Records a profile defined by a file of this app.
    def register_profile(profile)
      @profiles[profile.name] = profile
    end

    # The deployments of robot +name+, loaded from config/robots/NAME.rb.
    def robot_config(name = 'default')
      @robot_configs[name] ||= load_robot_config(name)
    end

    # The robot configuration file being evaluated, for Syskit.conf.
    attr_reader :loading_robot_config

    def robot_config_names
      Dir[File.join(root, 'config', 'robots', '*.rb')].map { |p| File.basename(p, '.rb') }.sort
    end

    # Resolves the model and driver of every device of every profile.
    def resolve_devices
      index = Robot::DriverIndex.new(orogen, self)
      ErrorList.raise_if_any(profiles.values.flat_map { |p| p.robot.resolve(index) })
    end

    private

    def read_config
      path = File.join(root, CONFIG_FILE)
      return {} unless File.file?(path)

      Psych.safe_load(File.read(path), filename: path) || {}
    rescue Psych::Exception => e
      raise FileLoadError.new("cannot read #{CONFIG_FILE}: #{e.message}", location: Location.new(path, 1))
    end

    def robot_names(robots)
      robots == :all ? robot_config_names : Array(robots)
    end

    def collect_problems
      yield
    rescue Syskit::ErrorList => e
      @problems.concat(e.errors)
    rescue Syskit::Error => e
      @problems << e
    end

    def load_bundled_models
      load_file(File.join(BUNDLED_MODELS, 'devices', 'bus', 'can.rb'))
    end

    def load_everything
      app_orogen = File.join(root, 'models', 'orogen')
      app_libraries = Dir[File.join(app_orogen, '*.{orogen,rb}')].map do |f|
        File.basename(f).sub(/\.(orogen|rb)\z/, '')
      end
      app_libraries.uniq.sort.each do |lib|
        spec = orogen.spec_path(lib)
        collect_problems do
          raise extension_without_library(lib) unless spec

          using_task_library(lib, location: Location.new(spec, 1))
        end
      end
      Dir[File.join(root, 'models', 'typekits', '*.rb')].each do |path|
        collect_problems { import_types(File.basename(path, '.rb'), location: Location.new(path, 1)) }
      end
    end

    def extension_without_library(lib)
      FileLoadError.new(
        "this file extends task library '#{lib}', but there is no #{lib}.orogen" \
        "#{Naming.did_you_mean(lib, orogen.available_library_names)}",
        location: Location.new(File.join(root, 'models', 'orogen', "#{lib}.rb"), 1),
        hint: "name the file after its task library, or add models/orogen/#{lib}.orogen"
      )
    end

    def load_robot_config(name)
      path = File.join(root, 'config', 'robots', "#{name}.rb")
      config = Config::RobotConfig.new(self, name)
      unless File.file?(path)
        raise FileLoadError.new(
          "no configuration for robot '#{name}'#{Naming.did_you_mean(name, robot_config_names)}",
          location: Location.new(path, 0),
          hint: "create config/robots/#{name}.rb with Syskit.conf.use_deployment statements"
        )
      end

      @loading_robot_config = config
      begin
        eval_in_namespace(File.read(path), path, namespace_for(path))
      ensure
        @loading_robot_config = nil
      end
      config
    end

    def replace_constant(name, value)
      Object.send(:remove_const, name) if Object.const_defined?(name, false)
      Object.const_set(name, value)
    end

    def owned_constant?(const)
      path, = Object.const_source_location(const)
      path.nil? || owned_file?(path)
    end

    def owned_file?(path)
      path.start_with?("#{root}/", "#{BUNDLED_MODELS}/")
    end
  end
end
