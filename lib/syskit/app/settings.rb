# frozen_string_literal: true

module Syskit
  class App
    # config/syskit.yml, checked: an app's name (a Ruby constant name, the
    # module its files are evaluated in), the acronyms its generators keep,
    # and the bundles it uses (see BundleSearch).
    #
    #   name: AwesomeRobot
    #   acronyms: [GPS, CAN, IMU]
    #   bundles: [common_models, ../other_bundle]
    class Settings
      KEYS = %w[name acronyms bundles].freeze

      attr_reader :path, :data, :name, :acronyms, :problems

      # The settings of the app at +root+; +name+ overrides the file's. A
      # setting that cannot be read is a problem (see #problems) and takes
      # its default; a name that is not a constant name is replaced by one
      # that is, so that the rest of the app can be checked.
      def initialize(root, name: nil)
        @path = File.join(root, CONFIG_FILE)
        @problems = []
        @data = collecting({}) { read }
        @acronyms = collecting([]) { list('acronyms') }
        @name = name || collecting(nil) { given_name } || Settings.default_name(root, @acronyms)
        return if Naming.constant_name?(@name)

        @problems << directory_name_error(root)
        @name = 'UnnamedApp'
      end

      # An app's name when config/syskit.yml gives none: its directory's,
      # camelized, dashes read as underscores as `bundle gem` reads them
      # (awesome_robot and awesome-robot -> AwesomeRobot).
      def self.default_name(root, acronyms = [])
        Naming.camelize(directory_words(File.basename(root)), acronyms)
      end

      # 'my-robot' -> 'my_robot': a directory name as words camelize joins.
      def self.directory_words(basename)
        basename.tr('-', '_')
      end

      def [](key)
        data[key]
      end

      private

      def collecting(default)
        yield
      rescue FileLoadError => e
        @problems << e
        default
      end

      def read
        return {} unless File.file?(path)

        data = Psych.safe_load(UserFile.read(path), filename: path) || {}
        raise shape_error('config/syskit.yml must map settings to values', 1) unless data.is_a?(Hash)

        unknown = data.keys - KEYS
        raise shape_error("unknown setting '#{unknown.first}'", line_of(unknown.first.to_s)) unless unknown.empty?

        data
      rescue Psych::Exception => e
        raise FileLoadError.new("cannot read #{CONFIG_FILE}: #{e.message}", location: Location.new(path, 1))
      end

      def given_name
        value = data['name']
        return if value.nil?
        return value if value.is_a?(String) && Naming.constant_name?(value)

        raise shape_error("the app name #{value.inspect} is not a Ruby constant name", line_of('name'),
                          hint: 'write name: AwesomeRobot (a letter first, then letters, digits and _)')
      end

      def list(key)
        value = data[key]
        return [] if value.nil?
        return value if value.is_a?(Array) && value.all?(String)

        raise shape_error("#{key} must be a list of names", line_of(key), hint: "write #{key}: [GPS, CAN]")
      end

      # An app whose directory's name makes no module name must be given one.
      def directory_name_error(root)
        FileLoadError.new(
          "the directory name '#{File.basename(root)}' does not make a Ruby module name ('#{@name}')",
          location: Location.new(path, 1),
          hint: 'give the app a name in config/syskit.yml: name: AwesomeRobot'
        )
      end

      def shape_error(message, line, hint: "settings: #{KEYS.join(', ')}")
        FileLoadError.new(message, location: Location.new(path, line), hint: hint)
      end

      def line_of(key)
        (UserFile.lines(path).index { |l| l.start_with?("#{key}:", "'#{key}'", "\"#{key}\"") } || 0) + 1
      end
    end
  end
end
