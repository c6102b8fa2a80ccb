# frozen_string_literal: true

module Syskit
  class App
    # A bundle: a directory with models/ and config/. An app is the first
    # bundle of its own list, then come the bundles it depends on, then the
    # gem's own small common_models (the CAN bus model, the canbus library
    # and a few typekits), which any real common_models bundle precedes.
    Bundle = Struct.new(:name, :root) do
      def to_s
        "bundle #{name} (#{root})"
      end
    end

    # Finds the bundles an app depends on, as Rock does: by name, in the
    # directories of SYSKIT_BUNDLE_PATH and ROCK_BUNDLE_PATH (each one a
    # bundle, or a directory of bundles), or by path. An app names them in
    # config/syskit.yml (+bundles: [common_models, ../other]+) or, as Rock
    # bundles do, in config/app.yml (+bundle: dependencies: [...]+) or
    # with +Roby.app.register_app 'path'+ in a robot configuration; the
    # bundles' own dependencies follow them.
    class BundleSearch
      ENV_VARS = %w[SYSKIT_BUNDLE_PATH ROCK_BUNDLE_PATH].freeze
      # Roby.app.register_app 'path' in robot configurations, read from their
      # text (they run after the models they make loadable).
      REGISTER_APP = /\bregister_app[\s(]+(['"])([^'"]+)\1/

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

      # The gem's own bundle, searched last.
      BUNDLED = Bundle.new('common_models', File.expand_path('../../../bundles/common_models', __dir__)).freeze

      private

      def each_dependency(bundle, config, errors)
        declared(bundle.root, config).each do |entry, location|
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
      def declared(root, config)
        from_syskit = list_at(config && config['bundles'], File.join(root, CONFIG_FILE), 'bundles')
        rock_config = File.join(root, 'config', 'app.yml')
        rock = File.file?(rock_config) ? rock_dependencies(rock_config) : []
        (from_syskit + rock + registered_apps(root)).uniq(&:first)
      end

      def registered_apps(root)
        Dir[File.join(root, 'config', 'robots', '*.rb')].select { |p| File.file?(p) }.flat_map do |path|
          UserFile.lines(path).each_with_index.filter_map do |line, i|
            m = line.match(REGISTER_APP)
            [m[2], Location.new(path, i + 1)] if m && !line.lstrip.start_with?('#')
          end
        end
      end

      def rock_dependencies(path)
        data = Psych.safe_load(UserFile.read(path), filename: path) || {}
        bundle = data.is_a?(Hash) ? data['bundle'] : nil
        list_at(bundle.is_a?(Hash) ? bundle['dependencies'] : nil, path, 'dependencies')
      rescue Psych::Exception => e
        raise FileLoadError.new("cannot read config/app.yml: #{e.message}", location: Location.new(path, 1))
      end

      # The entries of a list setting, each with the line it is written on.
      def list_at(value, path, key)
        return [] if value.nil?

        unless value.is_a?(Array) && value.all? { |v| v.is_a?(String) && !v.empty? }
          raise FileLoadError.new("#{key} must be a list of bundle names or paths",
                                  location: Location.new(path, line_of(path, key)),
                                  hint: "write #{key}: [common_models, ../my_other_bundle]")
        end

        value.map { |entry| [entry, Location.new(path, line_of(path, entry))] }
      end

      def line_of(path, text)
        (UserFile.lines(path).index { |l| l.include?(text) } || 0) + 1
      end

      # A path (with a /) relative to the bundle that names it, or a name
      # looked up in the bundle path.
      def find(entry, from, location)
        if entry.include?('/')
          root = File.expand_path(entry, from)
          return Bundle.new(File.basename(root), root) if bundle?(root)
        else
          root = candidates(entry).find { |dir| bundle?(dir) }
          return Bundle.new(entry, root) if root
          # Rock's common_models: the gem's own small one stands for it.
          return if entry == BUNDLED.name
        end

        raise missing(entry, location)
      end

      def candidates(name)
        @dirs.flat_map { |dir| File.basename(dir) == name ? [dir] : [File.join(dir, name)] }
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
