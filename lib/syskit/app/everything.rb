# frozen_string_literal: true

module Syskit
  class App
    # What `syskit check` loads besides what profiles ask for, so that the
    # problems of every file are found: each task library the app extends
    # or declares, each typekit it describes, and each configuration file,
    # checked against the task model it is named after.
    module Everything
      # Reads the configuration file at +path+ again (`syskit lsp`: an editor
      # changed it) without loading the rest again: the problems after the
      # first +kept+ (those a check added after loading) and those located
      # in the file are forgotten, the task model's configuration is read
      # anew when next asked for, and the file is checked again. Returns the
      # number of problems loading now accounts for.
      def reread_conf_file(path, kept:)
        path = File.expand_path(path)
        @conf_files&.delete(File.basename(path, '.yml'))
        problems.slice!(kept..)
        problems.reject! { |p| p.location&.path == path }
        @problem_keys = nil
        collect_problems { check_conf_file(path) } if File.file?(path) && app_conf_file?(path)
        problems.size
      end

      private

      def app_conf_file?(path)
        File.dirname(path) == File.join(root, 'config', 'orogen') && path.end_with?('.yml')
      end

      def load_everything
        load_app_libraries
        Files.ruby_files(File.join(root, 'models', 'typekits'), problems).each do |path|
          collect_problems { import_types(File.basename(path, '.rb'), location: Location.new(path, 1)) }
        end
        Dir[File.join(root, 'config', 'orogen', '*.yml')].select { |p| File.file?(p) }.each do |path|
          collect_problems { check_conf_file(path) }
        end
      end

      def load_app_libraries
        app_orogen = File.join(root, 'models', 'orogen')
        app_libraries = Files.ruby_files(app_orogen, problems, '*.{orogen,rb}').map do |f|
          File.basename(f).sub(/\.(orogen|rb)\z/, '')
        end
        app_libraries.uniq.each do |lib|
          spec = orogen.spec_path(lib)
          collect_problems do
            raise extension_without_library(lib) unless spec

            using_task_library(lib, location: Location.new(spec, 1))
          end
        end
      end

      # A warning: bundles extend libraries that are not installed
      # everywhere (Rock then does not load the file either), but it may be
      # a typo.
      def extension_without_library(lib)
        Warning.new(
          "this file extends task library '#{lib}', but there is no #{lib}.orogen on the search path: not loaded" \
          "#{Naming.did_you_mean(lib, orogen.available_library_names)}",
          location: Location.new(File.join(root, 'models', 'orogen', "#{lib}.rb"), 1),
          hint: "name the file after its task library, or add #{lib}.orogen to models/orogen or SYSKIT_OROGEN_PATH"
        )
      end

      # config/orogen/lib::Task.yml must name a task model: a typo in its
      # name would leave it unused without a word. A library that is on no
      # search path may be a component this machine does not have: a
      # warning. Every section is checked against the task model, used by
      # a profile or not (see Config::SectionValues).
      def check_conf_file(path)
        model_name = File.basename(path, '.yml')
        location = Location.new(path, 1)
        library, task = model_name.split('::', 2)
        raise conf_file_error("'#{model_name}' is not a task model name", location) unless task

        unless orogen.available_library_names.include?(library)
          raise Warning.new("no task library '#{library}' on the search path: this configuration file is not " \
                            "checked#{Naming.did_you_mean(library, orogen.available_library_names)}",
                            location: location, hint: "add #{library}.orogen to models/orogen or SYSKIT_OROGEN_PATH")
        end

        using_task_library(library, location: location)
        task_model = orogen.find_task_model(model_name)
        return check_sections(path, task_model) if task_model

        names = orogen.library(library).tasks.keys.sort
        raise conf_file_error("#{library} has no task model '#{model_name}'#{Naming.did_you_mean(model_name, names)}",
                              location)
      end

      # The file is the one the generator reads for +task_model+ (parsed
      # once) unless a bundle's comes first.
      def check_sections(path, task_model)
        file = conf_file(task_model)
        file = Config::ConfFile.new(path) unless file&.path == path
        ErrorList.raise_if_any(Config::SectionValues.problems(file, task_model))
      end

      def conf_file_error(message, location)
        ConfigurationError.new(message, location: location,
                                        hint: 'configuration files are named after their task model: ' \
                                              'config/orogen/<library>::<Task>.yml')
      end
    end
  end
end
