# frozen_string_literal: true

require 'syskit/app/bundle'

module Syskit
  class App
    # Finds the bundles an app depends on, as Rock does: by name, in the
    # directories of SYSKIT_BUNDLE_PATH and ROCK_BUNDLE_PATH (each one a
    # bundle, or a directory of bundles), or by path. An app names them in
    # config/syskit.yml (+bundles: [common_models, ../other]+) or, as Rock
    # bundles do, in config/app.yml (+bundle: dependencies: [...]+) or
    # with +Roby.app.register_app 'path'+ in a robot configuration; the
    # bundles' own dependencies follow them.
    class BundleSearch
      ENV_VARS = %w[SYSKIT_BUNDLE_PATH ROCK_BUNDLE_PATH].freeze

      def initialize(env = ENV)
        @dirs = ENV_VARS.flat_map { |var| env.fetch(var, '').split(File::PATH_SEPARATOR) }
                        .reject(&:empty?).map { |d| File.expand_path(d) }
      end

      # The bundles of the app at +root+ called +name+, itself first, and
      # the errors met (a bundle that is not found is left out).
      def resolve(root, name, config)
        found = [Bundle.new(name, root)]
        errors = []
        queue = [[found.first, config]]
        until queue.empty?
          bundle, bundle_config = queue.shift
          each_dependency(bundle, bundle_config, errors) do |dependency|
            next if found.any? { |b| b.root == dependency.root }

            found << dependency
            queue << [dependency, nil]
          end
        end
        found << BUNDLED unless found.any? { |b| b.root == BUNDLED.root }
        [found, errors]
      end

      # The gem's own bundle, searched last: the models/ directory at the
      # top of the gem (the CAN bus model, the canbus, iodrivers_base and
      # logger task libraries and a few typekits), required as Rock's
      # common_models ('common_models/models/devices/bus/can'). Only that
      # directory is the bundle's: the rest of the gem is never app code.
      BUNDLED = Bundle.new('common_models', File.expand_path('../../..', __dir__), dirs: ['models']).freeze

      private

      def each_dependency(bundle, config, errors)
        declared(bundle.root, config, errors).each do |entry, location|
          dependency = find(entry, bundle.root, location)
          yield dependency if dependency
        rescue FileLoadError => e
          errors << e
        end
      rescue FileLoadError => e
        errors << e
      end

      # [name or path, location] pairs a bundle declares. +config+ is the
      # app's config/syskit.yml, already read.
      def declared(root, config, errors)
        from_syskit = config&.yaml ? list_at(config['bundles'], config.yaml, 'bundles') : []
        rock_config = File.join(root, 'config', 'app.yml')
        rock = File.file?(rock_config) ? rock_dependencies(rock_config) : []
        (from_syskit + rock + registered_apps(root, errors)).uniq(&:first)
      end

      # Roby.app.register_app 'path' in robot configurations; a path
      # computed in Ruby is a warning (see RegisteredApps).
      def registered_apps(root, errors)
        Dir[File.join(root, 'config', 'robots', '*.rb')].select { |p| File.file?(p) }.sort.flat_map do |path|
          calls, warnings = RegisteredApps.of(path)
          errors.concat(warnings)
          calls
        end
      end

      def rock_dependencies(path)
        yaml = SettingsYaml.new(path)
        bundle = yaml.data.is_a?(Hash) ? yaml.data['bundle'] : nil
        list_at(bundle.is_a?(Hash) ? bundle['dependencies'] : nil, yaml, 'bundle', 'dependencies')
      end

      # The entries of a list setting at +keys+ of +yaml+, each with the
      # line it is written on.
      def list_at(value, yaml, *keys)
        return [] if value.nil?

        key_location = Location.new(yaml.path, yaml.key_line(*keys))
        unless value.is_a?(Array) && value.all? { |v| v.is_a?(String) && !v.empty? }
          raise FileLoadError.new("#{keys.last} must be a list of bundle names or paths",
                                  location: key_location,
                                  hint: "write #{keys.last}: [common_models, ../my_other_bundle]")
        end

        lines = yaml.item_lines(*keys)
        value.each_with_index.map { |entry, i| [entry, lines[i] ? Location.new(yaml.path, lines[i]) : key_location] }
      end

      # A path (with a /) relative to the bundle that names it, or a name
      # looked up in the bundle path.
      def find(entry, from, location)
        check_entry(entry, location)
        if entry.include?('/')
          root = File.expand_path(entry, from)
          return bundle_at(File.basename(root), root) if bundle?(root)

          raise not_a_bundle(entry, root, location) if File.directory?(root)
        else
          found = candidates(entry).select { |dir| File.directory?(dir) }
          root = found.find { |dir| bundle?(dir) }
          return bundle_at(entry, root) if root
          # Rock's common_models: the gem's own small one stands for it.
          return if entry == BUNDLED.name
          raise not_a_bundle(entry, found.first, location) if found.any?
        end

        raise missing(entry, location)
      end

      # Names and paths are text: a control character (a NUL byte that
      # YAML's "\0" writes) names no file.
      def check_entry(entry, location)
        return unless entry.match?(/[[:cntrl:]]/) || entry.strip.empty?

        raise FileLoadError.new(
          "#{entry.inspect} is not a bundle name or path#{' (it holds a control character)' unless entry.strip.empty?}",
          location: location, hint: 'write the name of a bundle (common_models) or a path to it (../my_bundle)'
        )
      end

      def not_a_bundle(entry, dir, location)
        FileLoadError.new(
          "'#{entry}' is #{dir}, a directory that is not a bundle: it has neither models/ nor config/",
          location: location,
          hint: 'name the bundle itself (the directory holding its models/ and config/), not its parent or a ' \
                'directory inside it'
        )
      end

      def candidates(name)
        @dirs.flat_map { |dir| File.basename(dir) == name ? [dir] : [File.join(dir, name)] }
      end

      # The bundle +name+ at +root+; this gem's own when +root+ is the gem
      # (a checkout named as a bundle): its models/ only, never its lib/.
      def bundle_at(name, root)
        File.identical?(root, BUNDLED.root) ? BUNDLED : Bundle.new(name, root)
      end

      def bundle?(dir)
        File.directory?(File.join(dir, 'models')) || File.directory?(File.join(dir, 'config'))
      end

      def missing(entry, location)
        where = @dirs.empty? ? 'SYSKIT_BUNDLE_PATH and ROCK_BUNDLE_PATH are not set' : "searched #{@dirs.join(', ')}"
        FileLoadError.new(
          "no bundle '#{entry}' (#{where})",
          location: location,
          hint: 'give a path relative to this app (../common_models), or add the directory holding the ' \
                'bundle to SYSKIT_BUNDLE_PATH'
        )
      end
    end
  end
end
