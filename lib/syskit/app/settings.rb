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

      # +yaml+: the SettingsYaml of the file, nil without one.
      attr_reader :path, :data, :name, :acronyms, :problems, :yaml

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
        problem = if !Naming.constant_name?(@name) then directory_name_error(root)
                  elsif Settings.taken_name?(@name) then taken_name_error
                  end
        return unless problem

        @problems << problem
        @name = 'UnnamedApp'
      end

      # Whether an app cannot be named +name+: its files are evaluated in
      # its module, which must be its own, not Ruby's Kernel nor the
      # OroGen, Roby or Conf an active app installs (its modules would be
      # nested in them, or fail later: "Conf is not a module").
      def self.taken_name?(name)
        !taken_by(name).nil?
      end

      # Who has +name+ already, for messages; nil when it is free.
      def self.taken_by(name)
        top = name.to_s.split('::').first.to_sym
        if Environment::INSTALLED.include?(top) || Compat.constants.key?(top)
          'a name Rock files use, which syskit defines while an app is loaded'
        elsif top == :Syskit then "syskit's own module"
        elsif Object.const_defined?(top, false) then 'a constant Ruby (or a library syskit loads) already defines'
        end
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

        @yaml = SettingsYaml.new(path)
        data = @yaml.data
        raise shape_error('config/syskit.yml must map settings to values', 1) unless data.is_a?(Hash)

        unknown = data.keys - KEYS
        unless unknown.empty?
          key = unknown.first
          raise shape_error("unknown setting #{shown_key(key)}", line_of(key.to_s))
        end

        data
      end

      def given_name
        value = data['name']
        return if value.nil?
        return value if value.is_a?(String) && Naming.constant_name?(value)

        raise shape_error("the app name #{value.inspect} is not a Ruby constant name", line_of('name'),
                          hint: 'write name: AwesomeRobot (a letter first, then letters, digits and _)')
      end

      def taken_name_error
        given = data['name'] == @name
        where = given ? "the app name '#{@name}'" : "the app name '#{@name}' (from its directory's name)"
        FileLoadError.new(
          "#{where} is taken: #{@name} is #{Settings.taken_by(@name)}; the app's modules would be defined " \
          'inside it',
          location: Location.new(path, given ? line_of('name') : 1),
          hint: "give the app a name of its own in config/syskit.yml, e.g. name: #{@name}Robot"
        )
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

      # A key as the user wrote it; bytes that are not text (a !!binary
      # key) are shown escaped.
      def shown_key(key)
        text = key.to_s.dup.force_encoding(Encoding::UTF_8)
        text.valid_encoding? ? "'#{text}'" : text.dump
      end

      def line_of(key)
        @yaml ? @yaml.key_line(key) : 1
      end
    end
  end
end
