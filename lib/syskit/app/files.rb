# frozen_string_literal: true

module Syskit
  class App
    # Evaluating the app's Ruby files. A file that opens no module at its
    # top level is evaluated inside the namespace its path names
    # (models/profiles/live/base.rb in AppName::Profiles::Live), so the
    # seed's short snippets work as written.
    module Files
      # The regular files *.rb of +dir+ (a glob), sorted. What only looks
      # like one (a directory named x.rb, a dangling symlink or one that
      # loops, a FIFO that reading would wait on forever) is not read: it
      # is a warning in +problems+.
      def self.ruby_files(dir, problems, pattern = '*.rb')
        Dir[File.join(dir, pattern)].select do |path|
          next true if File.file?(path)

          problems << Warning.new("#{File.basename(path)} is #{what_it_is(path)}, not a file: it is not loaded",
                                  location: Location.new(path, 1), hint: 'remove it or rename it')
          false
        end
      end

      def self.what_it_is(path)
        if File.symlink?(path) then File.exist?(path) ? 'a symlink to something else' : 'a broken symlink'
        elsif File.directory?(path) then 'a directory'
        elsif File.pipe?(path) then 'a named pipe'
        else 'not a regular file'
        end
      end

      # Loads a Ruby file of the app, once.
      def load_file(path)
        # The path as Ruby's require finds it through the load path (the
        # bundles' roots as given, symlinks kept), so that both mark a file
        # loaded under the same name.
        path = File.expand_path(path)
        names = names_of(path)
        if names.any? { |name| $LOADED_FEATURES.include?(name) }
          inherit_failure(path)
          return false
        end

        # Marked as loaded first, so that a file that fails is reported once
        # rather than evaluated again by a later `require` of it.
        $LOADED_FEATURES.concat(names)
        source = UserFile.read(path)
        modules = source.match?(/^(module|class)\s+[A-Z]/) ? [] : namespace_for(path)
        loading(path) { eval_in_namespace(source, path, modules) }
        true
      end

      # The file of the app or of its bundles that `require name` means
      # ('models/devices/gps', 'common_models/models/devices/bus/can'), nil
      # for any other library. DSL#require loads it with #load_file rather
      # than Kernel#require: Ruby re-indexes its loaded features on the next
      # require after each file an app marks loaded (tens of milliseconds
      # in a process with a few hundred features), and a file required
      # before its turn is then evaluated as every app file is.
      def required_file(name)
        file = name.end_with?('.rb') ? name : "#{name}.rb"
        return (file if File.file?(file) && environment_file?(file)) if file.start_with?('/')
        return if file.start_with?('./', '../')

        @environment.require_dirs.each do |dir|
          path = File.join(dir, file)
          return path if File.file?(path)
        end
        bundles.lazy.filter_map { |bundle| bundle.named_file(file) }.first
      end

      # Records that the code at +location+ requires +path+, a file of the
      # app or of its bundles (see RobotFiles), and that the robot whose
      # configuration is loading loads it.
      def record_require(location, path)
        robot_files.required(location.path, path) if location
        loading_robot_config&.loaded_files&.<<(path)
      end

      def robot_files
        @robot_files ||= RobotFiles.new
      end

      # The names of the robots, of those loaded, whose configuration loads
      # +path+ (see RobotFiles).
      def robots_loading(path)
        robot_configs.select { |_, config| robot_files.reaches?(config.loaded_files, path) }.keys
      end

      # Evaluates a file that is not a model file (a robot configuration)
      # in the app's namespace, each time it is asked to.
      def eval_file(path)
        eval_in_namespace(UserFile.read(path), path, namespace_for(path))
      end

      # The require path ('models/services/pose') of the file of the app or
      # of its bundles that, by the layout's convention, defines +constant+
      # ('Services::Pose', 'AppName::Services::Pose'); nil when there is none.
      def file_defining(constant)
        segments = constant.to_s.split('::').reject(&:empty?)
        # The app's or a bundle's own module may lead the name (AppName::, CommonModels::).
        [0, 1].each do |dropped|
          kept = segments.drop(dropped)
          kept.size.downto(2) do |n|
            path = File.join('models', *kept.first(n).map { |s| Naming.underscore(s) })
            return path if bundles.any? { |bundle| bundle.file("#{path}.rb") }
          end
        end
        nil
      end

      private

      # Model files in load order: devices first, then other model
      # directories, then profiles. Task-library files (models/orogen) and
      # typekits are loaded when something asks for them.
      def each_model_file
        models = File.join(root, 'models', '')
        Files.ruby_files(File.join(models, '**'), problems).filter_map do |path|
          kind = path.delete_prefix(models).split('/').first
          next if %w[orogen typekits].include?(kind)

          [{ 'devices' => 0, 'profiles' => 2 }.fetch(kind, 1), path]
        end.sort.map(&:last)
      end

      def eval_in_namespace(source, path, modules)
        define_namespace(modules)
        # Only constant names (checked by namespace_for) reach the source.
        prefix = modules.map { |m| "module #{m};" }.join(' ')
        suffix = "\nend" * modules.size
        # The prefix shares the first line with the file, so line numbers hold.
        UserCode.guard(path: path, root: root) do
          ISeqCache.compile(modules.empty? ? source : "#{prefix} #{source}#{suffix}", path).eval
        rescue Exception => e # rubocop:disable Lint/RescueException -- re-raised, to the guard
          record_failure(path, e)
          mark_loaded(e)
          raise
        end
      end

      # Ruby forgets a required file that raised, so a later require would
      # evaluate it again and report what follows from its first half
      # ("already defined"): the app's files the error went through stay
      # loaded, and remember that they failed.
      def mark_loaded(exception)
        (exception.backtrace_locations || []).each do |loc|
          file = loc.absolute_path || loc.path
          next unless loc.label == '<top (required)>' && environment_file?(file) && File.file?(file)

          record_failure(file, exception)
          names_of(file).each { |name| $LOADED_FEATURES << name unless $LOADED_FEATURES.include?(name) }
        end
      end

      def record_failure(file, exception)
        (@load_failures ||= {})[File.realpath(file)] ||= Location.of_exception(exception)
      end

      # The app files being evaluated, innermost last.
      def loading(path)
        (@loading ||= []).push(path)
        yield
      ensure
        @loading.pop
      end

      # A file that requires one that failed earlier (and so is not
      # evaluated again) is incomplete too: it fails where that one did.
      def inherit_failure(required)
        failure = file_load_failure(required)
        requirer = @loading&.last
        (@load_failures[File.realpath(requirer)] ||= failure) if failure && requirer
      end

      public

      # Where the error was that stopped the file +require_path+ (of the app
      # or a bundle: 'models/compositions/control/generator') from loading,
      # or nil when it did not fail.
      def load_failure(require_path)
        return unless @load_failures

        bundle_files(require_path).lazy.filter_map { |file| file_load_failure(file) }.first
      end

      # Where the error was that stopped the file at +path+ from loading
      # (in it, or in a file it requires), or nil when it did not fail.
      def file_load_failure(path)
        @load_failures&.[](File.realpath(path)) if File.file?(path)
      end

      # Where an app file failed that declares using_task_library +name+
      # (so that the library is missing because of it), nil when none did.
      def failed_user_of_library(name)
        pattern = /using_task_library[\s(]*['"]#{Regexp.escape(name)}['"]/
        @load_failures&.find { |file, _| File.file?(file) && UserFile.read(file).match?(pattern) }&.last
      end

      # Whether the file +require_path+ of the app or a bundle is loaded.
      def loaded_file?(require_path)
        bundle_files(require_path).any? { |file| names_of(file).any? { |name| $LOADED_FEATURES.include?(name) } }
      end

      private

      def bundle_files(require_path)
        bundles.filter_map { |bundle| bundle.file("#{require_path}.rb") }
      end

      # The names Ruby's require may know +file+ by: its real path and its
      # path under each bundle root (which may be a symlink).
      def names_of(file)
        real = File.realpath(file)
        bundle_roots.filter_map do |root|
          real_root = File.realpath(root)
          "#{root}#{real.delete_prefix(real_root)}" if real.start_with?("#{real_root}/")
        end.push(real).uniq
      end

      # Module names a file without module statements is evaluated in. Files
      # of other bundles are evaluated as Rock does, at the top level.
      def namespace_for(path)
        return [] unless path.start_with?("#{root}/")

        relative = path.delete_prefix("#{root}/")
        dirs = File.dirname(relative).split('/')
        return [name] unless dirs.first == 'models' && !%w[orogen typekits].include?(dirs[1])

        [name] + dirs.drop(1).map { |d| module_name_of(d, path) }
      end

      def module_name_of(dir, path)
        module_name = Naming.camelize(dir, acronyms)
        return module_name if Naming.constant_name?(module_name)

        raise FileLoadError.new(
          'this file opens no module, so it is evaluated in the one its directory names, ' \
          "but '#{dir}' does not make a module name",
          location: Location.new(path, 1),
          hint: "rename the directory (letters, digits and _), or open the module in the file (module #{name} ...)"
        )
      end

      # Makes the modules +names+ (nested, from the top level) with
      # const_get/const_set, so that they exist before the file opens them.
      def define_namespace(names)
        names.reduce(Object) do |parent, child|
          if parent.const_defined?(child, false)
            parent.const_get(child, false)
          else
            parent.const_set(child, Module.new)
          end
        end
      end
    end
  end
end
