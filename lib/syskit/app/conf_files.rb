# frozen_string_literal: true

require 'syskit/config/conf_file'

module Syskit
  class App
    # The configuration files of the app's task models
    # (config/orogen/<library>::<Task>.yml, the app's over its bundles'),
    # and the sections a test stubs over them (syskit_stub_conf).
    module ConfFiles
      # The configuration of +task_model+ (config/orogen/<lib>::<Task>.yml),
      # nil when there is none. As in Rock, the files of the bundles and of
      # the app are all read, the app's last: its sections replace the
      # bundles' of the same name (or merge into them, with merge:true).
      #
      # Each file is read once: one that cannot be read raises the same
      # error to every task using it.
      def conf_file(task_model)
        @conf_files ||= {}
        file = @conf_files.fetch(task_model.name) { @conf_files[task_model.name] = read_conf_file(task_model.name) }
        raise file if file.is_a?(Syskit::Error)

        file
      end

      # Syskit's configuration manager of +task_model+: its configuration
      # (see #conf_file), an empty one when it has no file.
      def configuration_manager(task_model)
        conf_file(task_model) ||
          (@empty_conf_files ||= {})[task_model.name] ||= Config::ConfFile.empty("#{task_model.name}.yml")
      end

      # Merges +data+ into the sections +names+ of +task_model+ (made when
      # missing) until #clear_conf_stubs, as Syskit's syskit_stub_conf does.
      def stub_conf(task_model, names, data, location)
        file = conf_file(task_model) || Config::ConfFile.empty("#{task_model.name}.yml")
        (@stubbed_conf ||= []) << task_model.name
        @conf_files[task_model.name] = file.with_sections(names, data, location)
      end

      # Forgets the sections stubbed by #stub_conf: the files are read again.
      def clear_conf_stubs
        (@stubbed_conf || []).each { |name| @conf_files.delete(name) }
        @stubbed_conf = nil
      end

      private

      # The files of +model_name+, the app's over its bundles', or the error
      # that reading one raised.
      def read_conf_file(model_name)
        file = "#{model_name}.yml"
        paths = bundles.filter_map { |bundle| bundle.file(File.join('config', 'orogen', file)) }
        paths.reverse.reduce(nil) { |base, path| Config::ConfFile.new(path, base: base) }
      rescue Syskit::Error => e
        e
      end
    end
  end
end
